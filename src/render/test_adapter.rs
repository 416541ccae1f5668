//! Whether the tests that draw can run. A fresh machine may have no graphics adapter at all
//! (no GPU and no Mesa): those tests then skip with one line on stderr saying what to
//! install, so that `cargo test` passes there. CI sets `X3DCHECK_REQUIRE_GPU=1`, which
//! turns a missing adapter into a failure, so that the render tests cannot silently stop
//! running there.

use std::io::Write;
use std::sync::OnceLock;

/// The variable that makes a missing adapter a test failure (`.ci/run` sets it).
pub const REQUIRE_GPU: &str = "X3DCHECK_REQUIRE_GPU";

/// For a test that draws: true when an adapter exists. Without one it writes
/// "SKIPPED <test>: …" with what to install and returns false, or panics under
/// `X3DCHECK_REQUIRE_GPU=1`. The adapter is looked for once per process.
#[doc(hidden)]
pub fn adapter_for_test(test: &str) -> bool {
    static FOUND: OnceLock<bool> = OnceLock::new();
    if *FOUND.get_or_init(|| pollster::block_on(super::gpu::find_adapter()).is_some()) {
        return true;
    }
    let missing = super::GpuError::NoAdapter;
    if std::env::var_os(REQUIRE_GPU).is_some_and(|v| v == "1") {
        panic!("{test}: {missing}; {REQUIRE_GPU}=1 requires one");
    }
    // Straight to stderr: the test harness captures `eprintln!` of passing tests, and
    // a skip must be seen.
    let _ = writeln!(
        std::io::stderr(),
        "SKIPPED {test}: {missing}; set {REQUIRE_GPU}=1 to make this a failure"
    );
    false
}
