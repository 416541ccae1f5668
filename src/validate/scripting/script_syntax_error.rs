//! SCRIPT_SYNTAX_ERROR: a Script's ECMAScript code does not parse.

use super::{line_column, Place};
use crate::diagnostic::Diagnostic;
use crate::validate::Ctx;

crate::declare_rule! {
    /// ## What it does
    /// Parses the ECMAScript code of each Script (oxc's parser) and reports the first
    /// syntax error of each piece of code at its line and column in the X3D file: in the
    /// CDATA section or text of the XML element, in an `ecmascript:`/`javascript:` url
    /// string (of an XML attribute, a JSON string or a ClassicVRML string: escapes such as
    /// `&quot;`, `\"` and `\u0041` are decoded and the place is that of the character as
    /// written), or in JSON's `#sourceCode`. Code in a local `.js` file (read at the deep
    /// level only) or in a `data:` URL is reported at the url entry naming it, with the
    /// line and column inside that code in the message, as the report formats place a
    /// finding in the checked file.
    ///
    /// The code is parsed as browsers run it: as a script (not a module), non-strict
    /// unless it says `"use strict"`, after its `ecmascript:` scheme. X_ITE evaluates it
    /// with a direct `eval` inside a `with` statement, so `with` is accepted and a `return`
    /// outside any function is an error, as there. In an XML attribute a line break is a
    /// space (XML attribute-value normalization), so a `//` comment there runs to the end
    /// of the attribute: write code in a CDATA section, or line breaks as `&#10;`.
    ///
    /// ## Why it matters
    /// Code that does not parse never runs: the Script sends no events, and its
    /// `initialize` and event functions are never called.
    ///
    /// ## Example
    /// ```xml
    /// <Script DEF='S'><![CDATA[ecmascript:
    ///   function initialize() { x = ; }
    /// ]]></Script>
    /// ```
    ///
    /// ## Use instead
    /// Fix the code at the place given; a browser's console shows the same error.
    ///
    /// ## Clause
    /// 19775-1 29.2.1 Script node (29.4.1 Script); ISO/IEC 19777-1 (ECMAScript language
    /// binding); ECMA-262 (the language).
    /// > "The input stream is syntactically in error if the tokens in the stream of input elements cannot be parsed as a single instance of the goal nonterminal (Script or Module), with no tokens left over" (ECMA-262 5.1.4)
    ///
    /// The Script's code, parsed with the goal Script, is such a stream.
    pub static SCRIPT_SYNTAX_ERROR = {
        severity: Error,
        level: Standard,
        clause: "29.4.1",
        versions: "all",
        check: Some(check),
    }
}

fn check(ctx: &mut Ctx) {
    let mut found = Vec::new();
    for script in &ctx.scripts().scripts {
        for code in &script.parsed {
            let Some(error) = &code.result.error else {
                continue;
            };
            let diagnostic = match &code.place {
                Place::Document(mapped) => Diagnostic::new(
                    &SCRIPT_SYNTAX_ERROR,
                    mapped.span(error.start, error.end),
                    format!("Script code does not parse: {}", error.message),
                ),
                Place::Elsewhere { entry, name, code } => {
                    let (line, column) = line_column(code, error.start);
                    Diagnostic::new(
                        &SCRIPT_SYNTAX_ERROR,
                        *entry,
                        format!(
                            "Script code in {name} does not parse: line {line}, column {column}: {}",
                            error.message
                        ),
                    )
                }
            };
            found.push(diagnostic.node(script.node));
        }
    }
    for diagnostic in found {
        ctx.report(diagnostic);
    }
}
