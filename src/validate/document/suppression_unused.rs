//! SUPPRESSION_UNUSED: an inline `x3dcheck: ignore CODE` comment that suppresses nothing
//! where it stands; reported where a file's findings are gathered (`crate::suppress`).

crate::declare_rule! {
    /// ## What it does
    /// Reports a code (or code prefix, or `ALL`) of an inline suppression comment when no
    /// finding of it was suppressed in what the comment applies to, a code that names no
    /// rule, and an `x3dcheck:` comment that is not `x3dcheck: ignore CODE[, CODE]`.
    ///
    /// A comment applies to: in XML, the element that follows it, with everything inside
    /// that element, or the whole file when it comes before the root `X3D` element; in
    /// ClassicVRML and VRML97 (`# x3dcheck: ignore CODE`), the node, statement or field
    /// that follows it in the same parent, or the whole file when it comes before the
    /// first token after the header line; in JSON (`"#comment": "x3dcheck: ignore CODE"`),
    /// the next element of the array when the comment is an object of its own, the node
    /// whose object holds the member otherwise, and the whole file when it is in the
    /// top-level object, the `X3D` object or `head`.
    ///
    /// A code whose rule does not run (below the `--level`, or turned off by `--select`,
    /// `--ignore` or x3dcheck.toml) is not reported: the comment may be needed by another
    /// configuration. As ruff's RUF100, this finding is not suppressed by the comment it
    /// reports; a whole-file `x3dcheck: ignore SUPPRESSION_UNUSED` (or `ALL`) in another
    /// comment suppresses it.
    ///
    /// ## Why it matters
    /// A suppression that suppresses nothing is left over from a fixed finding, is
    /// misplaced, or misspells its code. Left in place, it would silently hide a later
    /// finding of that code that nobody has looked at.
    ///
    /// ## Example
    /// ```xml
    /// <!-- x3dcheck: ignore DEF_DUPLICATE -->
    /// <Transform DEF='Left'/>
    /// ```
    ///
    /// ## Use instead
    /// ```xml
    /// <Transform DEF='Left'/>
    /// ```
    ///
    /// ## Clause
    /// None: this concerns x3dcheck's own comments, not ISO/IEC 19775-1 (comments have no
    /// meaning in a scene: 19776-1 4.2, 19776-2 5.2.2, 19776-5 4.3.7).
    pub static SUPPRESSION_UNUSED = {
        severity: Hint,
        level: Standard,
        clause: "none",
        versions: "all",
    }
}
