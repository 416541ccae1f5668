//! Broken input never panics or hangs: a deterministic sample of the real corpus, each
//! file cut short, with bytes flipped, with a span repeated and with a span deleted, is
//! checked at the deep level. Every mutant must finish quickly and produce a report.

mod common;

use common::corpus_files;
use std::path::PathBuf;
use std::time::{Duration, Instant};

use x3dcheck::config::CheckConfig;
use x3dcheck::diagnostic::Level;

/// Every n-th corpus file (sorted by path), to keep the test to seconds.
const SAMPLE_EVERY: usize = 12;
/// Files above this size are skipped: mutants of big files only repeat the small ones.
const MAX_BYTES: usize = 256 * 1024;
const MAX_TIME_PER_MUTANT: Duration = Duration::from_secs(5);
/// How often the growth mutant repeats its span.
const GROWTH: usize = 2000;

/// SplitMix64: a fixed sequence, so a failure reproduces.
struct Rng(u64);

impl Rng {
    fn next(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^ (z >> 31)
    }

    fn below(&mut self, n: usize) -> usize {
        (self.next() % n.max(1) as u64) as usize
    }
}

fn sample() -> Vec<PathBuf> {
    corpus_files(&["x3d", "json", "x3dj"])
        .into_iter()
        .filter(|p| {
            matches!(
                p.extension().and_then(|e| e.to_str()),
                Some("x3d" | "json" | "x3dj")
            )
        })
        .step_by(SAMPLE_EVERY)
        .collect()
}

/// The mutants of one file: each a name and the mutated bytes.
fn mutants(bytes: &[u8], rng: &mut Rng) -> Vec<(String, Vec<u8>)> {
    let len = bytes.len();
    let mut out = Vec::new();
    for cut in [len / 7, len / 2, len.saturating_sub(3)] {
        out.push((format!("truncated at {cut}"), bytes[..cut].to_vec()));
    }
    let mut flipped = bytes.to_vec();
    let mut flips = Vec::new();
    for _ in 0..8 {
        let at = rng.below(len);
        let byte = rng.next() as u8;
        if let Some(b) = flipped.get_mut(at) {
            *b = byte;
            flips.push(at);
        }
    }
    out.push((format!("bytes replaced at {flips:?}"), flipped));
    let (start, span) = (rng.below(len), 1 + rng.below(200));
    let end = (start + span).min(len);
    let mut repeated = bytes[..end].to_vec();
    repeated.extend_from_slice(&bytes[start..]);
    out.push((format!("bytes {start}..{end} repeated"), repeated));
    let mut deleted = bytes[..start].to_vec();
    deleted.extend_from_slice(&bytes[end..]);
    out.push((format!("bytes {start}..{end} deleted"), deleted));
    // A short span repeated in place: an opening tag or bracket nests, a node or value
    // repeats thousands of times (what grows time or memory faster than the input).
    let end = (start + 1 + rng.below(40)).min(len);
    let mut grown = bytes[..start].to_vec();
    for _ in 0..GROWTH {
        grown.extend_from_slice(&bytes[start..end]);
    }
    grown.extend_from_slice(&bytes[start..]);
    out.push((
        format!("bytes {start}..{end} repeated {GROWTH} times"),
        grown,
    ));
    if bytes.trim_ascii_start().starts_with(b"{") {
        out.extend(json_mutants(bytes, rng));
    }
    out
}

/// JSON only: a number after a random place made huge, tiny or long, and a string's
/// closing quote dropped.
fn json_mutants(bytes: &[u8], rng: &mut Rng) -> Vec<(String, Vec<u8>)> {
    let mut out = Vec::new();
    let from = rng.below(bytes.len());
    if let Some(at) = bytes[from..]
        .iter()
        .position(u8::is_ascii_digit)
        .map(|i| from + i)
    {
        for number in [
            "1e999999999",
            "-1e-999999999",
            &"9".repeat(5000),
            "0x10",
            "01",
        ] {
            let mut mutant = bytes[..at].to_vec();
            mutant.extend_from_slice(number.as_bytes());
            mutant.extend_from_slice(&bytes[at..]);
            out.push((format!("{number:.12} inserted at {at}"), mutant));
        }
    }
    if let Some(at) = bytes[from..]
        .iter()
        .position(|&b| b == b'"')
        .map(|i| from + i)
    {
        let mut mutant = bytes.to_vec();
        mutant.remove(at);
        out.push((format!("quote at {at} removed"), mutant));
    }
    out
}

#[test]
fn mutated_corpus_files_are_checked_without_panic_or_hang() {
    let config = CheckConfig {
        level: Level::Deep,
        ..CheckConfig::default()
    };
    let mut rng = Rng(0x5EED);
    let mut problems = Vec::new();
    let mut checked = 0;
    for path in sample() {
        let bytes = std::fs::read(&path).unwrap();
        if bytes.len() > MAX_BYTES {
            continue;
        }
        for (what, mutant) in mutants(&bytes, &mut rng) {
            let name = format!("{} ({what})", path.display());
            let started = Instant::now();
            let result =
                std::panic::catch_unwind(|| x3dcheck::check_source(&name, &mutant, &config));
            checked += 1;
            if result.is_err() {
                problems.push(format!("{name}: panicked"));
            } else if started.elapsed() > MAX_TIME_PER_MUTANT {
                problems.push(format!("{name}: took {:?}", started.elapsed()));
            }
        }
    }
    assert!(checked > 300, "only {checked} mutants were checked");
    assert!(
        problems.is_empty(),
        "{} of {checked} mutants:\n{}",
        problems.len(),
        problems.join("\n")
    );
}

/// DEF/USE can make a small file stand for 2^199 node instances (a "billion laughs" made
/// of USE); whatever visits instances must not try to visit them all.
#[test]
fn exponential_use_expansion_is_checked_quickly() {
    let mut scene =
        String::from("<X3D profile='Interchange' version='4.0'><Scene><Group DEF='L0'/>");
    for i in 1..200 {
        scene.push_str(&format!(
            "<Group DEF='L{i}'><Group USE='L{}'/><Group USE='L{}'/></Group>",
            i - 1,
            i - 1
        ));
    }
    scene.push_str("<Shape><Box/></Shape></Scene></X3D>");
    let config = CheckConfig {
        level: Level::Deep,
        ..CheckConfig::default()
    };
    let started = Instant::now();
    let report = x3dcheck::check_source("laughs.x3d", scene.as_bytes(), &config);
    assert!(
        started.elapsed() < MAX_TIME_PER_MUTANT,
        "took {:?}",
        started.elapsed()
    );
    assert_eq!(report.stats.nodes, 202);
    let doc = x3dcheck::parse::read(scene.as_bytes()).document.unwrap();
    assert_eq!(doc.instances(), u64::MAX, "2^200 instances saturate");
}
