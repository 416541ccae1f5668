//! The floor: what any checker of the XML scene has to do at the least, and nothing else.
//! It reads the file, walks quick-xml's events, and parses every number of every
//! attribute with x3dcheck's number scanner into a vector, long values cut in pieces on
//! the pool's threads as x3dcheck cuts them. The benchmark runs it as a child process
//! (`x3dcheck-bench --floor FILE --floor-threads N`), timed and measured like the others.

use std::fs;
use std::path::Path;

use quick_xml::events::Event;
use quick_xml::Reader;
use rayon::prelude::*;
use x3dcheck::model::text::number::{is_separator, scan_float};
use x3dcheck::model::text::split;

/// Runs the floor on `path` with `threads` threads; prints how many numbers it read.
pub fn run(path: &Path, threads: usize) -> Result<(), String> {
    let pool = rayon::ThreadPoolBuilder::new()
        .num_threads(threads)
        .build()
        .map_err(|e| format!("cannot start worker threads: {e}"))?;
    let source = fs::read(path).map_err(|e| format!("cannot read {}: {e}", path.display()))?;
    let numbers = pool.install(|| numbers_of_document(&source))?;
    println!("{numbers} numbers");
    Ok(())
}

fn numbers_of_document(source: &[u8]) -> Result<usize, String> {
    let mut reader = Reader::from_reader(source);
    let mut numbers = 0;
    loop {
        match reader.read_event() {
            Ok(Event::Start(element) | Event::Empty(element)) => {
                for attribute in element.attributes() {
                    let attribute = attribute.map_err(|e| e.to_string())?;
                    numbers += numbers_of_value(attribute.value.as_bytes());
                }
            }
            Ok(Event::Eof) => return Ok(numbers),
            Ok(_) => {}
            Err(e) => return Err(format!("not well-formed: {e}")),
        }
    }
}

/// The numbers of one attribute value, in pieces when it is long.
fn numbers_of_value(s: &[u8]) -> usize {
    match split::piece_size(s.len(), rayon::current_num_threads) {
        None => numbers_of_piece(s, 0, s.len()),
        Some(piece) => split::pieces(s, piece)
            .into_par_iter()
            .map(|range| numbers_of_piece(s, range.start, range.end))
            .sum(),
    }
}

/// Parses the tokens of `s[start..end]` as floats into a vector (as a checker keeps
/// them), skipping those that are not numbers; returns how many were.
fn numbers_of_piece(s: &[u8], start: usize, end: usize) -> usize {
    let s = &s[..end];
    let mut values: Vec<f32> = Vec::with_capacity((end - start) / 4 + 1);
    let mut i = start;
    loop {
        while i < s.len() && is_separator(s[i]) {
            i += 1;
        }
        if i >= s.len() {
            return values.len();
        }
        match scan_float::<f32>(s, i) {
            Ok((value, after)) => {
                values.push(value);
                i = after;
            }
            Err(after) => i = after,
        }
    }
}
