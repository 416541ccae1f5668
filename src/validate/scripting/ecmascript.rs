//! Script code parsed as ECMAScript by oxc's parser, as X3D browsers run it: a script (not
//! a module) in non-strict code unless it says `"use strict"`. X_ITE evaluates it with a
//! direct `eval` inside `with (globalObject)`, so `with` is allowed and a `return` outside
//! a function is not; the parser is given the same rules.

use std::collections::HashSet;

use oxc_allocator::Allocator;
use oxc_ast::ast::{Expression, ForStatementInit, ForStatementLeft, Statement};
use oxc_parser::{ParseOptions, Parser};
use oxc_span::SourceType;

/// A syntax error at a byte range of the parsed code.
#[derive(Clone, Debug, PartialEq)]
pub struct SyntaxError {
    pub start: usize,
    pub end: usize,
    pub message: String,
}

/// What parsing one piece of Script code found.
#[derive(Debug, Default)]
pub struct Parsed {
    /// The first syntax error (the parser's later ones often follow from it).
    pub error: Option<SyntaxError>,
    /// Names the code binds when it runs, before any function is called: function, `var`,
    /// `let`, `const` and class declarations outside functions (blocks included), and names
    /// assigned by top-level expression statements (`f = function …`, `this.f = …`).
    pub names: HashSet<String>,
    /// The code may define names in ways not seen here (`eval`, `with`, `Function`).
    pub dynamic: bool,
}

/// Parses `code` on a thread with a stack deep enough for any nesting code of its length
/// can write (see [`crate::limits::MAX_SCRIPT_BYTES`]), or says why it was not parsed.
pub fn parse(code: &str) -> Result<Parsed, String> {
    use crate::limits::{MAX_SCRIPT_BYTES, SCRIPT_STACK_BASE, SCRIPT_STACK_PER_BYTE};
    if code.len() > MAX_SCRIPT_BYTES {
        return Err(format!(
            "is {} KiB long, more than the {} KiB x3dcheck parses, and is not checked",
            code.len() >> 10,
            MAX_SCRIPT_BYTES >> 10
        ));
    }
    let stack = SCRIPT_STACK_BASE + code.len() * SCRIPT_STACK_PER_BYTE;
    std::thread::scope(|scope| {
        std::thread::Builder::new()
            .name("x3dcheck-script".into())
            .stack_size(stack)
            .spawn_scoped(scope, || parse_here(code))
            .map_err(|e| format!("could not be parsed: no thread to parse it ({e})"))?
            .join()
            .map_err(|_| "could not be parsed: the parser failed".to_string())
    })
}

fn parse_here(code: &str) -> Parsed {
    let allocator = Allocator::default();
    let options = ParseOptions {
        allow_return_outside_function: false,
        ..ParseOptions::default()
    };
    let parsed = Parser::new(&allocator, code, SourceType::script())
        .with_options(options)
        .parse();
    let error = parsed.diagnostics.errors().next().map(|diagnostic| {
        let label = diagnostic
            .labels
            .iter()
            .find(|l| l.primary())
            .or(diagnostic.labels.first());
        let (start, end) = label.map_or((code.len(), code.len()), |l| {
            let start = (l.offset() as usize).min(code.len());
            (start, (start + l.len() as usize).min(code.len()))
        });
        SyntaxError {
            start,
            end,
            message: diagnostic.message.to_string(),
        }
    });
    let mut names = HashSet::new();
    let mut dynamic = code.contains("eval") || code.contains("Function");
    if error.is_none() {
        for statement in &parsed.program.body {
            bound_names(statement, &mut names, &mut dynamic);
        }
    }
    Parsed {
        error,
        names,
        dynamic,
    }
}

/// The names a statement outside any function binds (see [`Parsed::names`]).
fn bound_names(statement: &Statement, names: &mut HashSet<String>, dynamic: &mut bool) {
    let mut add = |name: &str| {
        names.insert(name.to_string());
    };
    match statement {
        Statement::FunctionDeclaration(function) => {
            if let Some(id) = &function.id {
                add(id.name.as_str());
            }
        }
        Statement::ClassDeclaration(class) => {
            if let Some(id) = &class.id {
                add(id.name.as_str());
            }
        }
        Statement::VariableDeclaration(declaration) => {
            for declarator in &declaration.declarations {
                for id in declarator.id.get_binding_identifiers() {
                    add(id.name.as_str());
                }
            }
        }
        Statement::ExpressionStatement(statement) => assigned(&statement.expression, names),
        Statement::BlockStatement(block) => {
            for inner in &block.body {
                bound_names(inner, names, dynamic);
            }
        }
        Statement::IfStatement(statement) => {
            bound_names(&statement.consequent, names, dynamic);
            if let Some(alternate) = &statement.alternate {
                bound_names(alternate, names, dynamic);
            }
        }
        Statement::ForStatement(statement) => {
            if let Some(ForStatementInit::VariableDeclaration(declaration)) = &statement.init {
                for declarator in &declaration.declarations {
                    for id in declarator.id.get_binding_identifiers() {
                        add(id.name.as_str());
                    }
                }
            }
            bound_names(&statement.body, names, dynamic);
        }
        Statement::ForInStatement(statement) => {
            for_left(&statement.left, names);
            bound_names(&statement.body, names, dynamic);
        }
        Statement::ForOfStatement(statement) => {
            for_left(&statement.left, names);
            bound_names(&statement.body, names, dynamic);
        }
        Statement::WhileStatement(statement) => bound_names(&statement.body, names, dynamic),
        Statement::DoWhileStatement(statement) => bound_names(&statement.body, names, dynamic),
        Statement::LabeledStatement(statement) => bound_names(&statement.body, names, dynamic),
        Statement::TryStatement(statement) => {
            for inner in &statement.block.body {
                bound_names(inner, names, dynamic);
            }
            if let Some(handler) = &statement.handler {
                for inner in &handler.body.body {
                    bound_names(inner, names, dynamic);
                }
            }
            if let Some(finalizer) = &statement.finalizer {
                for inner in &finalizer.body {
                    bound_names(inner, names, dynamic);
                }
            }
        }
        Statement::SwitchStatement(statement) => {
            for case in &statement.cases {
                for inner in &case.consequent {
                    bound_names(inner, names, dynamic);
                }
            }
        }
        Statement::WithStatement(_) => *dynamic = true,
        _ => {}
    }
}

fn for_left(left: &ForStatementLeft, names: &mut HashSet<String>) {
    if let ForStatementLeft::VariableDeclaration(declaration) = left {
        for declarator in &declaration.declarations {
            for id in declarator.id.get_binding_identifiers() {
                names.insert(id.name.to_string());
            }
        }
    }
}

/// Names an expression statement assigns: `a = …`, `a = b = …`, `this.a = …`, `a = 1, b = 2`.
fn assigned(expression: &Expression, names: &mut HashSet<String>) {
    match expression {
        Expression::AssignmentExpression(assignment) => {
            if let Some(name) = assignment.left.get_identifier_name() {
                names.insert(name.to_string());
            }
            assigned(&assignment.right, names);
        }
        Expression::SequenceExpression(sequence) => {
            for inner in &sequence.expressions {
                assigned(inner, names);
            }
        }
        Expression::ParenthesizedExpression(inner) => assigned(&inner.expression, names),
        _ => {}
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn declarations_and_top_level_assignments_bind_names() {
        let parsed = parse(
            "function a(v) { inner = 1; }\nvar b = function () {}, c;\nlet {d, e: [f]} = x;\n\
             g = h = function () {};\nthis.i = 1;\nif (x) { function j() {} } else { var k; }\n\
             for (var l in x) {}\ntry { var m; } catch (e) { var n; }\nclass O {}",
        )
        .unwrap();
        assert!(parsed.error.is_none(), "{:?}", parsed.error);
        let mut names: Vec<&str> = parsed.names.iter().map(String::as_str).collect();
        names.sort_unstable();
        assert_eq!(
            names,
            ["O", "a", "b", "c", "d", "f", "g", "h", "i", "j", "k", "l", "m", "n"]
        );
        assert!(!parsed.dynamic);
        assert!(parse("with (x) { var a; }").unwrap().dynamic);
    }

    #[test]
    fn syntax_errors_have_their_place() {
        let code = "function f() {\n  x = ;\n}";
        let error = parse(code).unwrap().error.unwrap();
        assert_eq!(&code[error.start..], ";\n}");
        // A return outside a function is an error, as in `eval`.
        let error = |code: &str| parse(code).unwrap().error;
        assert!(error("return 1;").is_some());
        // Non-strict code: `with` and octal literals parse.
        assert!(error("with (Math) { x = PI; } y = 010;").is_none());
        assert!(error("function f() {").is_some());
    }

    /// The parser recurses per nesting level: code nested as deep as its length allows
    /// parses without overflowing the stack, whatever thread checks it.
    #[test]
    fn the_deepest_nesting_does_not_overflow() {
        let n = crate::limits::MAX_SCRIPT_BYTES / 2 - 4;
        for (open, close) in [("[", "]"), ("(", ")"), ("{", "}"), ("!", ""), ("a?b:", "c")] {
            let code = format!(
                "x={}{}",
                open.repeat(n / open.len()),
                close.repeat(n / open.len())
            );
            let code = &code[..code.len().min(crate::limits::MAX_SCRIPT_BYTES)];
            assert!(parse(code).is_ok(), "{open}");
        }
        assert!(parse(&"x".repeat(crate::limits::MAX_SCRIPT_BYTES + 1)).is_err());
    }
}
