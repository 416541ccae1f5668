//! A bound on what a source's macros expand to, checked before glslang sees it: glslang's
//! preprocessor has no limit of its own, so ten lines of `#define A1 A0 A0` … or nested
//! calls of `#define F(x) x x` would expand to billions of tokens (hours and gigabytes).
//!
//! The bound is an over-estimate: each macro's expansion counts every macro in its body
//! at its own expansion's size, a function-like macro multiplies its arguments by the
//! number of times its body names a parameter (times what the macros in its body
//! multiply), and each level of macro calls nested in a call's arguments multiplies by
//! the largest such factor. Real shaders (a `SQR(x)` here and there, constants) stay far
//! below the limit.

use std::collections::HashMap;

/// Sources whose macros may expand past this many tokens are not compiled.
pub const MAX_EXPANDED_TOKENS: u64 = 4_000_000;

/// Sources nesting brackets deeper than this are not compiled: glslang walks its syntax
/// tree recursively, so `((((…))))` a hundred thousand deep would overflow the stack.
/// Real shaders nest a few dozen deep at most.
pub const MAX_NESTING: usize = 256;

/// Whether `(`, `[` and `{` nest at most [`MAX_NESTING`] deep (comments included: a
/// bound, not a parse).
pub fn nesting_within_bound(source: &str) -> bool {
    let mut depth = 0usize;
    for b in source.bytes() {
        match b {
            b'(' | b'[' | b'{' => {
                depth += 1;
                if depth > MAX_NESTING {
                    return false;
                }
            }
            b')' | b']' | b'}' => depth = depth.saturating_sub(1),
            _ => {}
        }
    }
    true
}

struct Macro<'a> {
    params: Vec<&'a str>,
    function: bool,
    body: Vec<&'a str>,
}

/// Whether the source's macros stay within [`MAX_EXPANDED_TOKENS`].
pub fn within_bound(source: &str) -> bool {
    if !source.contains("#") {
        return true;
    }
    let mut macros: HashMap<&str, Macro> = HashMap::new();
    let mut text_tokens: Vec<&str> = Vec::new();
    let lines = logical_lines(source);
    for line in &lines {
        let trimmed = line.trim_start();
        if let Some(directive) = trimmed.strip_prefix('#') {
            let directive = directive.trim_start();
            if let Some(rest) = directive.strip_prefix("define") {
                if let Some((name, m)) = parse_define(rest) {
                    macros.insert(name, m);
                }
            }
            continue;
        }
        text_tokens.extend(words(line));
    }
    if macros.is_empty() {
        return true;
    }
    let mut sizes: HashMap<&str, u64> = HashMap::new();
    let mut factors: HashMap<&str, u64> = HashMap::new();
    let names: Vec<&str> = macros.keys().copied().collect();
    for name in &names {
        size(name, &macros, &mut sizes, &mut Vec::new());
        factor(name, &macros, &mut factors, &mut Vec::new());
    }
    let pasting = macros.values().any(|m| m.body.contains(&"##"));
    let largest = sizes.values().copied().max().unwrap_or(1);
    let worst_factor = factors.values().copied().max().unwrap_or(1).max(1);
    // The tokens outside directives, each macro at its size.
    let mut total: u64 = 0;
    for token in &text_tokens {
        let each = match sizes.get(token) {
            Some(&s) if pasting => s.saturating_add(largest),
            Some(&s) => s,
            None => 1,
        };
        total = total.saturating_add(each);
    }
    // Nested macro calls: `F(F(F(x)))` multiplies by F's factor at each level, in the
    // text and in bodies (`#define APPLY(f) f(f(y))`, where a parameter may name a macro).
    let mut depth = call_depth(&text_tokens, |t| macros.contains_key(t));
    for m in macros.values() {
        let body_depth = call_depth(&m.body, |t| macros.contains_key(t) || m.params.contains(&t));
        depth = depth.saturating_add(body_depth);
    }
    let scale = worst_factor.checked_pow(depth).unwrap_or(u64::MAX);
    total.saturating_mul(scale) <= MAX_EXPANDED_TOKENS
}

/// Lines with `\`-newline continuations joined.
fn logical_lines(source: &str) -> Vec<String> {
    let mut lines = Vec::new();
    let mut current = String::new();
    for line in source.lines() {
        if let Some(head) = line.strip_suffix('\\') {
            current.push_str(head);
            current.push(' ');
        } else {
            current.push_str(line);
            lines.push(std::mem::take(&mut current));
        }
    }
    if !current.is_empty() {
        lines.push(current);
    }
    lines
}

fn parse_define(rest: &str) -> Option<(&str, Macro<'_>)> {
    if !rest.starts_with(char::is_whitespace) {
        return None;
    }
    let rest = rest.trim_start();
    let end = rest
        .find(|c: char| !(c.is_ascii_alphanumeric() || c == '_'))
        .unwrap_or(rest.len());
    let name = &rest[..end];
    if name.is_empty() {
        return None;
    }
    let after = &rest[end..];
    let (params, function, body) = if let Some(list) = after.strip_prefix('(') {
        let close = list.find(')')?;
        let params = list[..close]
            .split(',')
            .map(str::trim)
            .filter(|p| !p.is_empty())
            .collect();
        (params, true, &list[close + 1..])
    } else {
        (Vec::new(), false, after)
    };
    Some((
        name,
        Macro {
            params,
            function,
            body: words(body),
        },
    ))
}

/// Identifiers, `##`, and every other non-blank character as tokens (a rough count).
fn words(text: &str) -> Vec<&str> {
    let bytes = text.as_bytes();
    let mut found = Vec::new();
    let mut i = 0;
    while i < bytes.len() {
        let b = bytes[i];
        if b.is_ascii_whitespace() {
            i += 1;
            continue;
        }
        let start = i;
        if b.is_ascii_alphanumeric() || b == b'_' {
            while i < bytes.len() && (bytes[i].is_ascii_alphanumeric() || bytes[i] == b'_') {
                i += 1;
            }
        } else if bytes[i..].starts_with(b"##") {
            i += 2;
        } else {
            i += text[i..].chars().next().map_or(1, char::len_utf8);
        }
        found.push(&text[start..i]);
    }
    found
}

/// Tokens one use of `name` expands to with one-token arguments.
fn size<'a>(
    name: &'a str,
    macros: &HashMap<&'a str, Macro<'a>>,
    sizes: &mut HashMap<&'a str, u64>,
    active: &mut Vec<&'a str>,
) -> u64 {
    if let Some(&s) = sizes.get(name) {
        return s;
    }
    let Some(m) = macros.get(name) else { return 1 };
    if active.contains(&name) {
        return 1; // a macro is not expanded inside its own expansion
    }
    active.push(name);
    let mut total: u64 = 0;
    for token in &m.body {
        let each = if macros.contains_key(token) {
            size(token, macros, sizes, active)
        } else {
            1
        };
        total = total.saturating_add(each);
    }
    active.pop();
    let total = total.max(1);
    sizes.insert(name, total);
    total
}

/// How many times one use of `name` copies an argument.
fn factor<'a>(
    name: &'a str,
    macros: &HashMap<&'a str, Macro<'a>>,
    factors: &mut HashMap<&'a str, u64>,
    active: &mut Vec<&'a str>,
) -> u64 {
    if let Some(&f) = factors.get(name) {
        return f;
    }
    let Some(m) = macros.get(name) else { return 1 };
    if active.contains(&name) {
        return 1;
    }
    active.push(name);
    let uses = m.body.iter().filter(|t| m.params.contains(t)).count() as u64;
    let mut inner = 1u64;
    for token in &m.body {
        if macros.get(token).is_some_and(|t| t.function) {
            inner = inner.max(factor(token, macros, factors, active));
        }
    }
    active.pop();
    let result = if m.function {
        uses.max(1).saturating_mul(inner)
    } else {
        inner
    };
    factors.insert(name, result);
    result
}

/// The deepest nesting of macro calls (a name `is_macro` takes, followed by `(`).
fn call_depth(tokens: &[&str], is_macro: impl Fn(&str) -> bool) -> u32 {
    let mut stack: Vec<bool> = Vec::new();
    let mut calls = 0u32;
    let mut deepest = 0u32;
    for (i, token) in tokens.iter().enumerate() {
        match *token {
            "(" => {
                let call = i > 0 && is_macro(tokens[i - 1]);
                if call {
                    calls += 1;
                    deepest = deepest.max(calls);
                }
                stack.push(call);
            }
            // The guard pops for every ")"; only a macro call's closes a call.
            ")" if stack.pop() == Some(true) => calls = calls.saturating_sub(1),
            _ => {}
        }
    }
    deepest
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn deep_nesting_is_caught() {
        let deep = format!(
            "float f() {{ return {}1.0{}; }}",
            "(".repeat(10_000),
            ")".repeat(10_000)
        );
        assert!(!nesting_within_bound(&deep));
        assert!(nesting_within_bound(
            "void main() { if (a) { b[(1)] = 0; } }"
        ));
    }

    #[test]
    fn real_macros_pass() {
        let source = "#define PI 3.14159\n#define SQR(x) ((x) * (x))\nfloat f(float a) { return SQR(SQR(a)) * PI; }";
        assert!(within_bound(source));
        assert!(within_bound("void main() {}"));
    }

    #[test]
    fn doubling_chains_and_nested_calls_are_caught() {
        let mut chain = String::from("#define A0 x x\n");
        for k in 1..40 {
            chain.push_str(&format!("#define A{k} A{} A{}\n", k - 1, k - 1));
        }
        chain.push_str("A39\n");
        assert!(!within_bound(&chain));
        let nested = format!("#define F(x) x x\n{}y{}\n", "F(".repeat(40), ")".repeat(40));
        assert!(!within_bound(&nested));
    }
}
