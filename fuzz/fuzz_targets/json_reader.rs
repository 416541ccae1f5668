//! The JSON reader alone: any bytes in, a document or diagnostics out, never a panic.
#![no_main]

use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| {
    let _ = x3dcheck::parse::json::read(data);
});
