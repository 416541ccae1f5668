//! A Text geometry within the scene's character budget, its notes joining the report.

use super::{Context, Walker};
use crate::limits::MAX_RENDER_TEXT_CHARACTERS;
use crate::model::NodeId;
use crate::render::fields::boolean;
use crate::render::geometry::{Needs, Shading};
use crate::render::mesh::LocalMesh;
use crate::render::text;

impl Walker<'_> {
    /// Text (15.4.2) as a mesh; None when nothing is drawn (noted). Past the character
    /// budget the Text is left out (LIMIT_EXCEEDED) and the walk goes on.
    pub(super) fn text(
        &mut self,
        context: Context,
        geometry: NodeId,
        needs: &Needs,
        max_triangles: usize,
    ) -> Option<(LocalMesh, Shading)> {
        let doc = context.doc;
        let characters = text::characters(doc, geometry);
        if self.spent.text_characters + characters > MAX_RENDER_TEXT_CHARACTERS {
            self.push_note(
                context,
                geometry,
                format!(
                    "Text of {characters} characters is not drawn: a scene's Text is drawn up to \
                     {MAX_RENDER_TEXT_CHARACTERS} characters"
                ),
                true,
            );
            return None;
        }
        self.spent.text_characters += characters;
        let built = text::build(doc, geometry, needs, &mut self.glyphs, max_triangles);
        for note in built.notes {
            self.note(context, geometry, note);
        }
        // Text is two-sided unless it says otherwise (15.4.2: solid FALSE).
        let shading = Shading {
            solid: boolean(doc, geometry, "solid", false),
            unlit: false,
        };
        built.mesh.map(|mesh| (mesh, shading))
    }
}
