//! The whole check at the deep level: any bytes in (XML, JSON or neither), a report out,
//! never a panic. The document stands in a small directory tree of its own with a PNG, a
//! JPEG, a GIF, a broken image and an Inline target, so that url fields written by the
//! fuzzer (or found in the seeds) reach the file checks; nothing outside it is read.
#![no_main]

use std::path::PathBuf;
use std::sync::OnceLock;

use libfuzzer_sys::fuzz_target;
use x3dcheck::config::CheckConfig;
use x3dcheck::diagnostic::Level;

/// Smallest valid images of each decoded format, 1×1 pixel.
const PNG_1X1: &[u8] = &[
    0x89, 0x50, 0x4e, 0x47, 0x0d, 0x0a, 0x1a, 0x0a, 0, 0, 0, 13, b'I', b'H', b'D', b'R', 0, 0, 0,
    1, 0, 0, 0, 1, 8, 0, 0, 0, 0, 0x3a, 0x7e, 0x9b, 0x55, 0, 0, 0, 10, b'I', b'D', b'A', b'T',
    0x78, 0x9c, 0x63, 0x60, 0, 0, 0, 2, 0, 1, 0x73, 0x75, 0x01, 0x18, 0, 0, 0, 0, b'I', b'E',
    b'N', b'D', 0xae, 0x42, 0x60, 0x82,
];
const GIF_1X1: &[u8] = b"GIF89a\x01\x00\x01\x00\x00\x00\x00,\x00\x00\x00\x00\x01\x00\x01\x00\x00\x02\x02D\x01\x00;";

fn scene_path() -> &'static str {
    static PATH: OnceLock<String> = OnceLock::new();
    PATH.get_or_init(|| {
        let dir = std::env::temp_dir().join(format!("x3dcheck-fuzz-tree-{}", std::process::id()));
        let textures = dir.join("textures");
        std::fs::create_dir_all(&textures).expect("fuzz tree");
        let files: [(PathBuf, &[u8]); 5] = [
            (textures.join("a.png"), PNG_1X1),
            (dir.join("b.gif"), GIF_1X1),
            (dir.join("broken.jpg"), b"\xff\xd8\xff\xe0 not really"),
            (dir.join("inline.x3d"), b"<X3D version='4.0'><Scene/></X3D>"),
            (dir.join("c.png"), &PNG_1X1[..40]),
        ];
        for (path, bytes) in files {
            std::fs::write(path, bytes).expect("fuzz tree file");
        }
        dir.join("scene.x3d").to_string_lossy().into_owned()
    })
}

fuzz_target!(|data: &[u8]| {
    let config = CheckConfig {
        level: Level::Deep,
        ..CheckConfig::default()
    };
    let _ = x3dcheck::check::check_source(scene_path(), data, &config);
});
