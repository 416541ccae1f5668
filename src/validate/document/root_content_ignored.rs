//! ROOT_CONTENT_IGNORED: content of the X3D root or its head that X3D gives no meaning.

use crate::model::HeaderPart;
use crate::report::Diagnostic;
use crate::schema::{self, Version};
use crate::validate::{suggest, Ctx};

crate::declare_rule! {
    /// ## What it does
    /// Reports content that stands where an X3D document has no place for it:
    /// - under the X3D root, anything but `head` and `Scene` (and, in XML, the XML
    ///   Signature `ds:Signature` that the schema allows after the Scene): a node such as
    ///   `<Transform>` placed before the Scene, an unknown element, or in JSON a member of
    ///   the `X3D` object other than `head`, `Scene`, `encoding`, `JSON schema`, `@`
    ///   attributes and comments (a `-children` array may hold comments only);
    /// - under `head`, anything but the `component`, `unit` and `meta` statements.
    ///
    /// Whatever such content holds is not read: its nodes are not checked.
    ///
    /// ## Why it matters
    /// A browser builds the scene from the Scene alone, so a node outside it is never
    /// drawn and a misspelt statement (`<metta>`, `<Component>`) never takes effect, with
    /// no message.
    ///
    /// ## Example
    /// ```xml
    /// <X3D profile='Interchange' version='4.0'>
    ///   <Transform><Shape><Box/></Shape></Transform>
    ///   <Scene/>
    /// </X3D>
    /// ```
    ///
    /// ## Use instead
    /// ```xml
    /// <X3D profile='Interchange' version='4.0'>
    ///   <Scene><Transform><Shape><Box/></Shape></Transform></Scene>
    /// </X3D>
    /// ```
    ///
    /// ## Clause
    /// 19776-1 4.2.2 (the structure of an X3D file: the header in `head`, then the
    /// Scene) and 4.2.3 (the header's statements); x3d-4.0.xsd (X3D: head?, Scene,
    /// ds:Signature?; head: component*, unit*, meta*); the X3D JSON schema
    /// (`additionalProperties: false` on X3D and head).
    pub static ROOT_CONTENT_IGNORED = {
        severity: Error,
        level: Fast,
        clause: "19776-1 4.2.2",
        versions: "all",
        check: Some(check),
    }
}

fn check(ctx: &mut Ctx) {
    for ignored in &ctx.doc.ignored {
        if ctx.is_full() {
            return;
        }
        let name = &ignored.name.text;
        let (message, expected) = match ignored.part {
            HeaderPart::Root => (
                format!("`{name}` is ignored: the X3D root holds only head and Scene"),
                &["head", "Scene"][..],
            ),
            HeaderPart::Head => (
                format!("`{name}` is ignored: head holds only component, unit and meta statements"),
                &["component", "unit", "meta"][..],
            ),
        };
        let is_node = schema::schema(Version::LATEST).node(name).is_some();
        let help = suggest::help(name, expected.iter().copied())
            .or_else(|| is_node.then(|| "nodes belong in the Scene".to_string()));
        ctx.report(
            Diagnostic::new(&ROOT_CONTENT_IGNORED, ignored.name.span, message)
                .value(name.clone())
                .help_opt(help),
        );
    }
}
