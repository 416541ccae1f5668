//! Large inputs are mapped (src/read/mapped.rs): checked as they would be read, and a file
//! truncated while mapped ends the run with a message and exit code 2, not a crash.

use std::path::{Path, PathBuf};
#[cfg(unix)]
use std::process::Command;

use x3dcheck::config::CheckConfig;
use x3dcheck::limits::MAX_INPUT_BYTES;
use x3dcheck::read::{read_path, read_source, Contents, Source, MAP_BYTES};

/// A scene of about `MAP_BYTES` and more, with one finding near its end.
fn large_scene(path: &Path) {
    let points = "0.5 1.25 -3 ".repeat(MAP_BYTES as usize / 12 + 1000);
    let scene = format!(
        "<X3D profile='Interchange' version='4.0'><Scene><Shape><PointSet>\
         <Coordinate point='{points}'/></PointSet></Shape>\
         <Transform scale='1 1 1' bogus='1'/></Scene></X3D>\n"
    );
    std::fs::write(path, scene).unwrap();
}

fn scratch(name: &str) -> PathBuf {
    std::env::temp_dir().join(format!("x3dcheck-mapped-{}-{name}", std::process::id()))
}

#[test]
fn a_mapped_file_gets_the_report_of_the_file_read() {
    let path = scratch("report.x3d");
    large_scene(&path);
    let Ok(Contents::Bytes(mapped)) = read_source(&path, MAX_INPUT_BYTES) else {
        panic!("not read");
    };
    assert!(matches!(mapped, Source::Mapped(_)));
    let Ok(Contents::Bytes(read)) = read_path(&path, MAX_INPUT_BYTES) else {
        panic!("not read");
    };
    let config = CheckConfig::default();
    let name = path.display().to_string();
    let from_map =
        x3dcheck::check::check_document_with_progress(&name, &mapped, &config, mapped.progress());
    let from_heap = x3dcheck::check::check_document(&name, &read, &config);
    assert!(!from_heap.report.diagnostics.is_empty());
    assert_eq!(from_map.report.diagnostics, from_heap.report.diagnostics);
    // The text is still whole after the passes gave their pages back.
    assert_eq!(&*from_map.text, &read[..]);
    std::fs::remove_file(&path).unwrap();
}

/// The child's side of the test below: maps the file, truncates it, then checks it.
const TRUNCATE_AND_CHECK: &str = "X3DCHECK_TEST_TRUNCATE_AND_CHECK";

/// Unix only: Windows refuses to truncate a mapped file.
#[cfg(unix)]
#[test]
fn a_mapped_file_truncated_while_checked_ends_the_run_with_a_message() {
    if let Some(path) = std::env::var_os(TRUNCATE_AND_CHECK) {
        let Ok(Contents::Bytes(source)) = read_source(Path::new(&path), MAX_INPUT_BYTES) else {
            panic!("not read");
        };
        assert!(matches!(source, Source::Mapped(_)));
        std::fs::OpenOptions::new()
            .write(true)
            .open(&path)
            .unwrap()
            .set_len(100)
            .unwrap();
        let config = CheckConfig::default();
        x3dcheck::check::check_document_with_progress("t", &source, &config, source.progress());
        panic!("the truncated file was read to its end");
    }
    let path = scratch("truncated.x3d");
    large_scene(&path);
    let test = "a_mapped_file_truncated_while_checked_ends_the_run_with_a_message";
    let child = Command::new(std::env::current_exe().unwrap())
        .args(["--exact", test, "--nocapture", "--test-threads=1"])
        .env(TRUNCATE_AND_CHECK, &path)
        .output()
        .unwrap();
    std::fs::remove_file(&path).unwrap();
    let stderr = String::from_utf8_lossy(&child.stderr);
    assert_eq!(child.status.code(), Some(2), "{stderr}");
    assert!(
        stderr.contains("x3dcheck: an input file shrank while it was read; no report\n"),
        "{stderr}"
    );
}
