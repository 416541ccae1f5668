// Empty: a build script makes Cargo resolve `[build-dependencies]`, whose features are
// the host build's (proc macros), pinned here too.
fn main() {}
