//! Path patterns for `[[per-path-ignores]]`, in the style of `.gitignore` and ruff's
//! per-file-ignores: `*` matches within one path segment, `**` any number of whole
//! segments, `?` one character other than `/`. Paths use `/` separators. A pattern without
//! a `/` matches a file's name in any directory (`*.json` everywhere).

#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Glob {
    segments: Vec<String>,
    /// A pattern without `/`: matched against the last path segment only.
    name_only: bool,
}

impl Glob {
    pub fn new(pattern: &str) -> Glob {
        let pattern = pattern.trim_start_matches("./");
        Glob {
            name_only: !pattern.contains('/'),
            segments: pattern
                .split('/')
                .filter(|s| !s.is_empty())
                .map(str::to_string)
                .collect(),
        }
    }

    /// Whether `path` (relative, `/`-separated) matches.
    pub fn matches(&self, path: &str) -> bool {
        let parts: Vec<&str> = path
            .split('/')
            .filter(|s| !s.is_empty() && *s != ".")
            .collect();
        if self.name_only {
            return match (self.segments.first(), parts.last()) {
                (Some(pattern), Some(name)) => segment_matches(pattern, name),
                _ => false,
            };
        }
        let segments: Vec<&str> = self.segments.iter().map(String::as_str).collect();
        path_matches(&segments, &parts)
    }
}

/// Segment-wise match with `**` standing for zero or more segments. Memoized over
/// (pattern position, path position), so it is O(pattern × path).
fn path_matches(pattern: &[&str], path: &[&str]) -> bool {
    let mut memo = vec![vec![None; path.len() + 1]; pattern.len() + 1];
    path_matches_at(pattern, path, 0, 0, &mut memo)
}

fn path_matches_at(
    pattern: &[&str],
    path: &[&str],
    p: usize,
    q: usize,
    memo: &mut Vec<Vec<Option<bool>>>,
) -> bool {
    if let Some(known) = memo[p][q] {
        return known;
    }
    let result = match pattern.get(p) {
        None => q == path.len(),
        Some(&"**") => {
            path_matches_at(pattern, path, p + 1, q, memo)
                || (q < path.len() && path_matches_at(pattern, path, p, q + 1, memo))
        }
        Some(segment) => {
            q < path.len()
                && segment_matches(segment, path[q])
                && path_matches_at(pattern, path, p + 1, q + 1, memo)
        }
    };
    memo[p][q] = Some(result);
    result
}

/// `*` and `?` within one segment: the classic two-pointer wildcard match, linear-ish.
fn segment_matches(pattern: &str, text: &str) -> bool {
    let (pattern, text): (Vec<char>, Vec<char>) =
        (pattern.chars().collect(), text.chars().collect());
    let (mut p, mut t) = (0, 0);
    let mut star: Option<(usize, usize)> = None;
    while t < text.len() {
        if p < pattern.len() && (pattern[p] == '?' || pattern[p] == text[t]) {
            p += 1;
            t += 1;
        } else if p < pattern.len() && pattern[p] == '*' {
            star = Some((p, t));
            p += 1;
        } else if let Some((star_p, star_t)) = star {
            p = star_p + 1;
            t = star_t + 1;
            star = Some((star_p, star_t + 1));
        } else {
            return false;
        }
    }
    pattern[p..].iter().all(|&c| c == '*')
}

#[cfg(test)]
mod tests {
    use super::Glob;

    #[test]
    fn name_patterns_match_anywhere() {
        let g = Glob::new("*.json");
        assert!(g.matches("a.json") && g.matches("deep/down/b.json"));
        assert!(!g.matches("a.x3d") && !g.matches("json/a.x3d"));
    }

    #[test]
    fn path_patterns_anchor_at_the_config_directory() {
        let g = Glob::new("legacy/*.x3d");
        assert!(g.matches("legacy/a.x3d"));
        assert!(!g.matches("legacy/sub/a.x3d") && !g.matches("other/legacy/a.x3d"));
        let deep = Glob::new("legacy/**/*.x3d");
        assert!(deep.matches("legacy/a.x3d") && deep.matches("legacy/x/y/a.x3d"));
        let any = Glob::new("**/generated/**");
        assert!(any.matches("generated/a.x3d") && any.matches("x/generated/y/b.x3d"));
        assert!(!any.matches("x/generator/b.x3d"));
        assert!(Glob::new("./scenes/a?.x3d").matches("scenes/ab.x3d"));
    }

    #[test]
    fn stars_do_not_cross_segments_and_stay_linear() {
        assert!(!Glob::new("a/*").matches("a/b/c"));
        let long = format!("a/{}", "*a".repeat(30));
        assert!(!Glob::new(&long).matches(&format!("a/{}b", "a".repeat(60))));
        assert!(Glob::new("a/**/**/**/b").matches(&format!("a/{}b", "x/".repeat(200))));
    }
}
