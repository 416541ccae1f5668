//! SCRIPT_HANDLER_MISSING: a Script input field with no function to receive its events.

use crate::diagnostic::Diagnostic;
use crate::schema::AccessType;
use crate::validate::Ctx;

crate::declare_rule! {
    /// ## What it does
    /// Reports a field a Script declares `inputOnly` that receives events (a ROUTE sends
    /// events to it, or it is connected by `IS` to a prototype's interface) whose
    /// ECMAScript code has no function of the field's name, and one declared `inputOutput`
    /// that other nodes route events to whose code has neither a function of its name nor
    /// one named `set_` + its name. A field no event reaches loses nothing.
    ///
    /// What was read, and where: ISO/IEC 19777-1 (the ECMAScript binding; VRML97's Annex C.4
    /// "eventIn handling" before it, C.4.1 "Receiving eventIns") has an input event passed
    /// to the script function of the same name, with the value and the time stamp as its
    /// arguments. X_ITE looks each one up after running the code once, by name, among the
    /// names the code bound (`typeof name`): for an inputOnly field its own name, for an
    /// inputOutput field `set_` + its name. A name counts here whatever binds it at the top
    /// level of the code (outside any function, blocks included): a function declaration,
    /// `var`, `let`, `const` or a class, and a top-level assignment (`f = function …`,
    /// `this.f = …`). For an inputOutput field both its name and `set_` + its name count,
    /// and only a routed one is reported: its value is stored whatever the code does, and
    /// many Scripts read it without a function.
    ///
    /// Not reported (to stay free of false reports): a Script whose code is not all read
    /// (a network URL, another language, a `.js` file below the deep level, a url passed in
    /// through IS), whose code does not parse (SCRIPT_SYNTAX_ERROR), or that uses `eval`,
    /// `Function` or `with`, which can bind names unseen.
    ///
    /// ## Why it matters
    /// The events routed to the field are dropped: the Script never reacts to them.
    ///
    /// ## Example
    /// ```xml
    /// <Script DEF='S'>
    ///   <field name='set_fraction' type='SFFloat' accessType='inputOnly'/>
    ///   <![CDATA[ecmascript: function fraction(value) { } ]]>
    /// </Script>
    /// <TimeSensor DEF='Clock' loop='true'/>
    /// <ROUTE fromNode='Clock' fromField='fraction_changed' toNode='S' toField='set_fraction'/>
    /// ```
    ///
    /// ## Use instead
    /// Name the function as the field (`function set_fraction(value, time) { … }`), or the
    /// field as the function.
    ///
    /// ## Clause
    /// ISO/IEC 19777-1 (ECMAScript language binding; 14772-1 Annex C.4.1 Receiving
    /// eventIns); 19775-1 29.2.2 Script execution.
    pub static SCRIPT_HANDLER_MISSING = {
        severity: Warning,
        level: Standard,
        clause: "29.2.2",
        versions: "all",
        check: Some(check),
    }
}

fn check(ctx: &mut Ctx) {
    let mut found = Vec::new();
    for script in &ctx.scripts().scripts {
        let readable = script.complete
            && !script.parsed.is_empty()
            && script
                .parsed
                .iter()
                .all(|code| code.result.error.is_none() && !code.result.dynamic);
        if !readable {
            continue;
        }
        let bound = |name: &str| script.parsed.iter().any(|c| c.result.names.contains(name));
        let node = ctx.doc.node(script.node);
        let def = node.def_name.as_ref().map(|d| d.text.as_str());
        for field in &node.declared {
            let name = field.name.text.as_str();
            let setter = format!("set_{name}");
            let message = match field.access {
                Some(AccessType::InputOnly)
                    if !bound(name) && (routed_to(ctx, def, name) || node.is_connected(name)) =>
                {
                    format!(
                    "Script field `{name}` (inputOnly) gets events but the code has no function `{name}` to receive them"
                    )
                }
                Some(AccessType::InputOutput)
                    if !bound(name)
                        && !bound(&setter)
                        && routed_to(ctx, def, name)
                        && !node.is_connected(name)
                        && !routed_from(ctx, def, name)
                        && !script.parsed.iter().any(|c| mentions(c.code(), name)) =>
                {
                    format!(
                        "Script field `{name}` (inputOutput) gets routed events but the code has no function `{setter}` or `{name}` to receive them"
                    )
                }
                _ => continue,
            };
            let help = (!is_identifier(name)).then(|| {
                format!("`{name}` is not an ECMAScript identifier, so no function can have its name: rename the field")
            });
            found.push(
                Diagnostic::new(&SCRIPT_HANDLER_MISSING, field.name.span, message)
                    .help_opt(help)
                    .node(script.node),
            );
        }
    }
    for diagnostic in found {
        ctx.report(diagnostic);
    }
}

/// Whether a ROUTE sends events to field `name` (or `set_name`) of the node DEF'd `def`.
fn routed_to(ctx: &Ctx, def: Option<&str>, name: &str) -> bool {
    let Some(def) = def else {
        return false;
    };
    ctx.doc.routes.iter().any(|route| {
        route.to_node.text == def
            && (route.to_field.text == name
                || route.to_field.text.strip_prefix("set_") == Some(name))
    })
}

/// Whether a ROUTE reads field `name` (or `name_changed`) of the node DEF'd `def`.
fn routed_from(ctx: &Ctx, def: Option<&str>, name: &str) -> bool {
    let Some(def) = def else {
        return false;
    };
    ctx.doc.routes.iter().any(|route| {
        route.from_node.text == def
            && (route.from_field.text == name
                || route.from_field.text.strip_suffix("_changed") == Some(name))
    })
}

/// Whether `code` has `name` as a whole word anywhere (read, written, in a comment).
fn mentions(code: &str, name: &str) -> bool {
    let is_word = |c: char| c.is_alphanumeric() || c == '_' || c == '$';
    code.match_indices(name).any(|(at, _)| {
        let before = code[..at].chars().next_back();
        let after = code[at + name.len()..].chars().next();
        !before.is_some_and(is_word) && !after.is_some_and(is_word)
    })
}

/// Whether `name` can name a function: an identifier that is not a reserved word.
fn is_identifier(name: &str) -> bool {
    const RESERVED: &[&str] = &[
        "break",
        "case",
        "catch",
        "class",
        "const",
        "continue",
        "debugger",
        "default",
        "delete",
        "do",
        "else",
        "enum",
        "export",
        "extends",
        "false",
        "finally",
        "for",
        "function",
        "if",
        "import",
        "in",
        "instanceof",
        "new",
        "null",
        "return",
        "super",
        "switch",
        "this",
        "throw",
        "true",
        "try",
        "typeof",
        "var",
        "void",
        "while",
        "with",
    ];
    let mut chars = name.chars();
    chars
        .next()
        .is_some_and(|c| c.is_alphabetic() || c == '_' || c == '$')
        && chars.all(|c| c.is_alphanumeric() || c == '_' || c == '$')
        && !RESERVED.contains(&name)
}
