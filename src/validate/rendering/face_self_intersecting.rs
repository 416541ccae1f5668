//! FACE_SELF_INTERSECTING: an IndexedFaceSet face whose edges cross (deep level).

use super::geometry::ScalarSpans;
use crate::diagnostic::Diagnostic;
use crate::validate::Ctx;

crate::declare_rule! {
    /// ## What it does
    /// Reports an IndexedFaceSet with a face whose outline crosses itself (a bow-tie
    /// quad, a star drawn in one stroke), in one diagnostic per geometry that names the
    /// first such face and its two crossing edges and counts the faces. Each face of four
    /// or more distinct corners is projected onto its plane (Newell's normal, the sum of
    /// its fan's cross products; for a face whose loops cancel that sum, the fan's largest
    /// cross product), and every pair of non-adjacent edges is tested for a proper
    /// crossing in f64: each edge's ends lie on opposite sides of the other's line, by
    /// more than a sine of 1e-6. Touching at a vertex, a vertex on another edge and edges
    /// that overlap along a line (a hole joined to its outline by a bridge traversed
    /// twice) are not crossings.
    ///
    /// Not judged: triangles (they cannot cross themselves), faces of zero area or with an
    /// unresolvable corner (DEGENERATE_TRIANGLE, INDEX_OUT_OF_RANGE), faces not planar
    /// (a corner off the plane by more than 1e-3 of the face's size: FACE_NOT_PLANAR or
    /// FACE_NOT_CONVEX report them, and a warped face has no outline in a plane).
    /// Repeated consecutive corners count once. Faces of more than 64 corners are swept
    /// along one axis rather than testing every pair of edges, with the same findings.
    /// The face walk is DEGENERATE_TRIANGLE's, made once for both.
    ///
    /// With `convex` TRUE (the default) FACE_NOT_CONVEX reports the same face as
    /// concave; this rule says what is wrong with it, and that `convex='false'` does not
    /// help: a crossing outline has no inside for a triangulation to fill.
    ///
    /// ## Why it matters
    /// A browser fans or triangulates the face from its corners, and a crossing outline
    /// gives triangles that overlap or fold back: the face draws differently in each
    /// browser, with holes or doubled areas, and its normal is not defined.
    ///
    /// ## Example
    /// ```xml
    /// <IndexedFaceSet convex='false' coordIndex='0 1 2 3 -1'>
    ///   <Coordinate point='0 0 0 1 1 0 1 0 0 0 1 0'/>
    /// </IndexedFaceSet>
    /// ```
    ///
    /// ## Use instead
    /// Order the corners around the outline (`0 2 1 3`), or split the face into the
    /// polygons it was meant to be (here, two triangles meeting at the crossing point).
    ///
    /// ## Clause
    /// 19775-1 13.3.6 IndexedFaceSet, as ISO/IEC 14772-1 6.23 for VRML97 (read in Coin3D's
    /// SoVRMLIndexedFaceSet documentation, which quotes the VRML97 text, and H3D's
    /// IndexedFaceSet): "Each face of the IndexedFaceSet shall have: at least three
    /// non-coincident vertices; vertices that define a planar polygon; vertices that
    /// define a non-self-intersecting polygon. Otherwise, The results are undefined." A
    /// warning: the sentence states the outcome, undefined results.
    pub static FACE_SELF_INTERSECTING = {
        severity: Warning,
        level: Deep,
        clause: "13.3.6",
        versions: "all",
        check: Some(check),
    }
}

fn check(ctx: &mut Ctx) {
    let surveyed = ctx.face_survey();
    for (geometry, survey) in surveyed.iter() {
        let Some(count) = &survey.crossing else {
            continue;
        };
        let Some((number, position, edges)) = count.first else {
            continue;
        };
        let mut spans = geometry
            .node
            .entry("coordIndex")
            .map(|entry| ScalarSpans::new(ctx.source, entry));
        let span = match spans.as_mut() {
            Some(spans) => spans.span(edges.first.0),
            None => geometry.node.name_span,
        };
        let edge = |(a, b): (usize, usize)| format!("coordIndex[{a}]–[{b}]");
        let message = format!(
            "{} of the {} faces of this IndexedFaceSet {} (first: face {number}, at coordIndex[{position}]: its edges {} and {} cross): its rendering is undefined",
            count.crossing,
            count.total,
            if count.crossing == 1 {
                "crosses itself"
            } else {
                "cross themselves"
            },
            edge(edges.first),
            edge(edges.second),
        );
        let mut diagnostic = Diagnostic::new(&FACE_SELF_INTERSECTING, span, message)
            .node(geometry.id)
            .index(position)
            .help(
                "order each face's corners around its outline, or split the face into \
                 polygons that do not cross; convex='false' does not help",
            );
        diagnostic.count = count.crossing;
        ctx.report(diagnostic);
    }
}
