//! Number scanners shared by the readers.
//!
//! A token of up to eight bytes of digits and one `.` (or, for integers, up to eight
//! digits) followed by a separator, the shape of nearly every coordinate, is read in one
//! 64-bit word: where it ends and where its `.` is come from one mask of the bytes that
//! are not digits, and its digits, moved side by side over the `.`, are converted in one
//! multiply-and-shift sequence, with no branch per byte. Any other token is scanned byte
//! by byte (its longer runs of digits eight at a time) with the significant digits
//! gathered into a `u64` as they go by. Either way, when the digits and the decimal exponent are small enough, the result is
//! one IEEE multiplication or division of two exactly representable operands, and hence
//! correctly rounded (Clinger's fast path). Anything else goes to the standard library's
//! parser, which is correctly rounded too. Single precision is converted directly from the
//! decimal text, never through `f64` (which would round twice).
//!
//! The `scan_*` functions read one token starting at a given offset in a larger text and
//! say where it ends; the `parse_*` functions read a whole token and nothing else.
//!
//! Written by hand rather than with a float crate because it measured best: on the
//! benchmark scene's MF values (callgrind, a loop over every float token), this scanner
//! took 183 instructions per float, fast-float2 0.2 191 and lexical-parse-float 1.0 223,
//! with the same wall time for the first two. The standard library's slow path is itself
//! fast_float's Eisel-Lemire algorithm, so a crate would not speed it up either. The
//! one-word path then took the XML reader's loop over the 0.25 benchmark scene's values
//! (callgrind, `-j 1`, skipping separators and storing each number included) from 177 to
//! 143 instructions per float and from 124 to 89 per integer.

/// True for the bytes that separate values in the XML encoding: XML whitespace and the
/// comma, which X3D treats as whitespace.
#[inline(always)]
pub fn is_separator(b: u8) -> bool {
    matches!(b, b' ' | b'\t' | b'\n' | b'\r' | b',')
}

/// The end of the token starting at `start`: the first separator at or after it, or the
/// end of the text.
#[inline]
pub fn token_end(s: &[u8], start: usize) -> usize {
    let mut i = start;
    while i < s.len() && !is_separator(s[i]) {
        i += 1;
    }
    i
}

/// Exact powers of ten as `u64`, 10^0 through 10^19.
const U64_POW10: [u64; 20] = [
    1,
    10,
    100,
    1_000,
    10_000,
    100_000,
    1_000_000,
    10_000_000,
    100_000_000,
    1_000_000_000,
    10_000_000_000,
    100_000_000_000,
    1_000_000_000_000,
    10_000_000_000_000,
    100_000_000_000_000,
    1_000_000_000_000_000,
    10_000_000_000_000_000,
    100_000_000_000_000_000,
    1_000_000_000_000_000_000,
    10_000_000_000_000_000_000,
];

/// A binary floating-point type the scanner can produce.
pub trait Float: Copy + PartialEq + std::fmt::Debug {
    /// Largest integer mantissa that converts exactly (2^24 for f32, 2^53 for f64).
    const MANTISSA_LIMIT: u64;
    /// Largest decimal exponent whose power of ten is exact in this type.
    const EXPONENT_LIMIT: i64;
    const ZERO: Self;
    const INFINITY: Self;
    const NAN: Self;
    /// 10^e for 0 ≤ e ≤ `EXPONENT_LIMIT`; each entry exact.
    fn pow10(e: usize) -> Self;
    /// Exact for `m` ≤ `MANTISSA_LIMIT`.
    fn from_mantissa(m: u64) -> Self;
    fn mul(self, other: Self) -> Self;
    fn div(self, other: Self) -> Self;
    fn neg(self) -> Self;
    /// `-self` when `negative`, without a branch (random signs would mispredict).
    fn with_sign(self, negative: bool) -> Self;
    /// The standard library's correctly rounded parser.
    fn parse_std(text: &str) -> Option<Self>;
    /// A second fast path through a wider type, where one exists; `None` when it cannot
    /// give the correctly rounded `m × 10^e`.
    #[inline(always)]
    fn fast_wide(_m: u64, _e: i64) -> Option<Self> {
        None
    }
}

const F32_POW10: [f32; 11] = [1e0, 1e1, 1e2, 1e3, 1e4, 1e5, 1e6, 1e7, 1e8, 1e9, 1e10];
const F64_POW10: [f64; 23] = [
    1e0, 1e1, 1e2, 1e3, 1e4, 1e5, 1e6, 1e7, 1e8, 1e9, 1e10, 1e11, 1e12, 1e13, 1e14, 1e15, 1e16,
    1e17, 1e18, 1e19, 1e20, 1e21, 1e22,
];

impl Float for f32 {
    const MANTISSA_LIMIT: u64 = 1 << 24;
    const EXPONENT_LIMIT: i64 = 10;
    const ZERO: f32 = 0.0;
    const INFINITY: f32 = f32::INFINITY;
    const NAN: f32 = f32::NAN;
    #[inline(always)]
    fn pow10(e: usize) -> f32 {
        F32_POW10[e]
    }
    #[inline(always)]
    fn from_mantissa(m: u64) -> f32 {
        m as f32
    }
    #[inline(always)]
    fn mul(self, other: f32) -> f32 {
        self * other
    }
    #[inline(always)]
    fn div(self, other: f32) -> f32 {
        self / other
    }
    #[inline(always)]
    fn neg(self) -> f32 {
        -self
    }
    #[inline(always)]
    fn with_sign(self, negative: bool) -> f32 {
        f32::from_bits(self.to_bits() ^ ((negative as u32) << 31))
    }
    fn parse_std(text: &str) -> Option<f32> {
        text.parse().ok()
    }

    /// `m × 10^e` rounded once to `f64` (Clinger's fast path for `f64`), then to `f32`.
    /// Rounding twice gives the wrong answer only when the `f64` result lands exactly on
    /// a midpoint between two `f32` values: every `f32` value and midpoint is an `f64`
    /// value too, and rounding is monotonic, so an exact value strictly between two
    /// midpoints rounds in `f64` to something between (or on) them. Midpoints are
    /// therefore refused here and left to the standard library, as is the `f32`
    /// subnormal range, where midpoints sit elsewhere. This takes the 8 and 9 digit
    /// numbers that shortest round-trip `f32` output is full of.
    #[inline(always)]
    fn fast_wide(m: u64, e: i64) -> Option<f32> {
        if m > f64::MANTISSA_LIMIT || !(-f64::EXPONENT_LIMIT..=f64::EXPONENT_LIMIT).contains(&e) {
            return None;
        }
        let r = if e >= 0 {
            m as f64 * F64_POW10[e as usize]
        } else {
            m as f64 / F64_POW10[(-e) as usize]
        };
        let bits = r.to_bits();
        // Below 2^-126 (biased f64 exponent 1023 - 126) f32 is subnormal.
        if (bits >> 52) & 0x7ff < 1023 - 126 {
            return None;
        }
        // The 29 low mantissa bits are what f32 drops; exactly half of that range is a
        // midpoint.
        if bits & ((1 << 29) - 1) == 1 << 28 {
            return None;
        }
        Some(r as f32)
    }
}

impl Float for f64 {
    const MANTISSA_LIMIT: u64 = 1 << 53;
    const EXPONENT_LIMIT: i64 = 22;
    const ZERO: f64 = 0.0;
    const INFINITY: f64 = f64::INFINITY;
    const NAN: f64 = f64::NAN;
    #[inline(always)]
    fn pow10(e: usize) -> f64 {
        F64_POW10[e]
    }
    #[inline(always)]
    fn from_mantissa(m: u64) -> f64 {
        m as f64
    }
    #[inline(always)]
    fn mul(self, other: f64) -> f64 {
        self * other
    }
    #[inline(always)]
    fn div(self, other: f64) -> f64 {
        self / other
    }
    #[inline(always)]
    fn neg(self) -> f64 {
        -self
    }
    #[inline(always)]
    fn with_sign(self, negative: bool) -> f64 {
        f64::from_bits(self.to_bits() ^ ((negative as u64) << 63))
    }
    fn parse_std(text: &str) -> Option<f64> {
        text.parse().ok()
    }
}

/// Clinger's fast path: `m × 10^e` when that is one correctly rounded operation.
#[inline(always)]
fn fast_path<F: Float>(m: u64, e: i64) -> Option<F> {
    // First, for f32, the wider path: it covers nearly everything the narrow one does
    // (all but exact midpoints) and more, and trying the narrow one first would cost a
    // mispredicted branch whenever the digit count varies around 7 to 9.
    if let Some(v) = F::fast_wide(m, e) {
        return Some(v);
    }
    if m <= F::MANTISSA_LIMIT {
        if (0..=F::EXPONENT_LIMIT).contains(&e) {
            return Some(F::from_mantissa(m).mul(F::pow10(e as usize)));
        }
        if (-F::EXPONENT_LIMIT..0).contains(&e) {
            return Some(F::from_mantissa(m).div(F::pow10((-e) as usize)));
        }
    }
    fast_path_extended(m, e)
}

/// The fast path after dropping trailing zeros from the mantissa (`0.500000000000`) and
/// moving surplus exponent into the mantissa while it stays exact (`3e12` for f32).
#[cold]
#[inline(never)]
fn fast_path_extended<F: Float>(mut m: u64, mut e: i64) -> Option<F> {
    if m == 0 {
        return Some(F::ZERO);
    }
    while m > F::MANTISSA_LIMIT && m.is_multiple_of(10) {
        m /= 10;
        e += 1;
    }
    if let Some(v) = F::fast_wide(m, e) {
        return Some(v);
    }
    if m > F::MANTISSA_LIMIT {
        return None;
    }
    if e > F::EXPONENT_LIMIT {
        let k = e - F::EXPONENT_LIMIT;
        if k >= U64_POW10.len() as i64 {
            return None;
        }
        m = m.checked_mul(U64_POW10[k as usize])?;
        if m > F::MANTISSA_LIMIT {
            return None;
        }
        e = F::EXPONENT_LIMIT;
    }
    if (0..=F::EXPONENT_LIMIT).contains(&e) {
        Some(F::from_mantissa(m).mul(F::pow10(e as usize)))
    } else if (-F::EXPONENT_LIMIT..0).contains(&e) {
        Some(F::from_mantissa(m).div(F::pow10((-e) as usize)))
    } else {
        None
    }
}

/// An optional `+` or `-` at `s[i]`: whether it is `-`, and the offset after it. Without
/// branches, since signs in coordinates follow no pattern a predictor could learn.
#[inline(always)]
fn scan_sign(s: &[u8], i: usize) -> (bool, usize) {
    let c = s.get(i).copied().unwrap_or(0);
    let negative = c == b'-';
    (negative, i + (negative | (c == b'+')) as usize)
}

/// The bytes of `chunk` that are not ASCII digits: some bit of each such byte is set, no
/// bit of the others. Per byte, the high nibble must be 3 and the low one at most 9; no
/// carries cross bytes.
#[inline(always)]
fn non_digit_bytes(chunk: u64) -> u64 {
    const ONES: u64 = 0x0101_0101_0101_0101;
    ((chunk & (0xF0 * ONES)) ^ (0x30 * ONES))
        | (((chunk & (0x0F * ONES)) + 0x06 * ONES) & (0xF0 * ONES))
}

/// How many of the eight bytes of `chunk` (read little-endian: the text's first byte is
/// the lowest) are ASCII digits before the first that is not; 8 when all are.
#[inline(always)]
pub(crate) fn leading_digits(chunk: u64) -> u32 {
    non_digit_bytes(chunk).trailing_zeros() / 8
}

/// Reads the decimal digits starting at `s[i]` into `m` (`m × 10^k + digits`, wrapping
/// on overflow: the caller counts the digits) and returns where they end. Eight bytes
/// at a time where the text allows, which saves a mispredicted branch per number.
#[inline(always)]
fn scan_digits(s: &[u8], mut i: usize, m: &mut u64) -> usize {
    while let Some(bytes) = s.get(i..i + 8) {
        let chunk = u64::from_le_bytes(bytes.try_into().unwrap_or([0; 8]));
        let k = leading_digits(chunk);
        if k == 0 {
            return i;
        }
        *m = m
            .wrapping_mul(U64_POW10[k as usize])
            .wrapping_add(digits_value(chunk, k as usize));
        i += k as usize;
        if k < 8 {
            return i;
        }
    }
    while i < s.len() {
        let d = s[i].wrapping_sub(b'0');
        if d > 9 {
            break;
        }
        *m = m.wrapping_mul(10).wrapping_add(d as u64);
        i += 1;
    }
    i
}

/// The value of the first `k` bytes of `chunk` (read little-endian), 1 ≤ k ≤ 8, all ASCII
/// digits.
#[inline(always)]
fn digits_value(chunk: u64, k: usize) -> u64 {
    const ONES: u64 = 0x0101_0101_0101_0101;
    // The k digits' values moved to the top bytes, with zeros (digit 0) below them
    // standing for leading zeros of an eight-digit number. Borrows from the bytes after
    // the digits only go upwards, and those are shifted out.
    eight_digits(chunk.wrapping_sub(0x30 * ONES) << (64 - 8 * k))
}

/// The value of eight digit values (0–9) packed in a `u64`, the first digit in the
/// lowest byte.
#[inline(always)]
fn eight_digits(v: u64) -> u64 {
    const MASK: u64 = 0x0000_00FF_0000_00FF;
    const MUL1: u64 = 100 + (1_000_000 << 32);
    const MUL2: u64 = 1 + (10_000 << 32);
    let v = v.wrapping_mul(10).wrapping_add(v >> 8);
    ((v & MASK)
        .wrapping_mul(MUL1)
        .wrapping_add(((v >> 16) & MASK).wrapping_mul(MUL2)))
        >> 32
}

/// Reads the float token starting at `s[start]`:
/// `[+-]?(digits[.digits?]|.digits)([eE][+-]?digits)?`, or `[+-]?(inf|infinity|nan)` in any
/// case (which covers the XML Schema forms `INF`, `-INF` and `NaN`). The token must end
/// at a separator or at the end of `s`.
///
/// Returns the value and the offset just past the token, or on a syntax error the offset
/// where the offending token ends.
#[inline(always)]
pub fn scan_float<F: Float>(s: &[u8], start: usize) -> Result<(F, usize), usize> {
    match scan_short_decimal(s, start) {
        Some(short) => Ok(short),
        None => scan_float_general(s, start),
    }
}

/// The nine bytes of `s` from `i`, the first eight as one little-endian word (the first
/// byte lowest), when there are that many: a token of up to eight bytes and the byte after
/// it.
#[inline(always)]
fn short_window(s: &[u8], i: usize) -> Option<(u64, &[u8; 9])> {
    let bytes = s.get(i..)?.first_chunk::<9>()?;
    let (word, _) = bytes.split_first_chunk::<8>()?;
    Some((u64::from_le_bytes(*word), bytes))
}

/// [`scan_float`] for the shape nearly every coordinate has: up to eight bytes of digits
/// with at most one `.` after an optional sign, then a separator (so not at the end of the
/// text). The token's end and its `.` are found in one word ([`non_digit_bytes`]), the
/// digits side by side without the `.` read in one go ([`digits_value`]), with no branch
/// per byte; the value is Clinger's fast path on the same mantissa and exponent as in
/// the general scan. `None` for anything else, which the general scan then reads from the
/// start.
#[inline(always)]
fn scan_short_decimal<F: Float>(s: &[u8], start: usize) -> Option<(F, usize)> {
    let (negative, i) = scan_sign(s, start);
    let (word, bytes) = short_window(s, i)?;
    let non_digits = non_digit_bytes(word);
    let int_digits = (non_digits.trailing_zeros() / 8) as usize;
    let dot = if int_digits < 8 && bytes[int_digits] == b'.' {
        0xFF << (8 * int_digits)
    } else {
        0
    };
    // The byte after the token: the first non-digit but the dot, or the ninth.
    let end = ((non_digits & !dot).trailing_zeros() / 8) as usize;
    let digits = end - (dot != 0) as usize;
    if digits == 0 || !is_separator(bytes[end]) {
        return None;
    }
    // The bytes before the dot, and those after it moved down by one over it; without a
    // dot, all of the word.
    let before_dot = (dot & dot.wrapping_neg()).wrapping_sub(1);
    let side_by_side = (word & before_dot) | ((word >> 8) & !before_dot);
    let m = digits_value(side_by_side, digits);
    let v = fast_path::<F>(m, int_digits as i64 - digits as i64)?;
    Some((v.with_sign(negative), i + end))
}

/// [`scan_float`] for any token.
#[inline(never)]
fn scan_float_general<F: Float>(s: &[u8], start: usize) -> Result<(F, usize), usize> {
    let n = s.len();
    let (negative, mut i) = scan_sign(s, start);
    let mut m: u64 = 0;
    let int_start = i;
    // Integer parts are short (often a single digit): a byte loop is quicker for them
    // than eight at a time, which pays off for the longer fractions.
    while i < n {
        let d = s[i].wrapping_sub(b'0');
        if d > 9 {
            break;
        }
        m = m.wrapping_mul(10).wrapping_add(d as u64);
        i += 1;
    }
    let mut digits = i - int_start;
    let mut fraction_digits = 0usize;
    if i < n && s[i] == b'.' {
        i += 1;
        let fraction_start = i;
        i = scan_digits(s, i, &mut m);
        fraction_digits = i - fraction_start;
        digits += fraction_digits;
    }
    if digits == 0 {
        return scan_special(s, start);
    }
    let mut exponent: i64 = 0;
    if i < n && (s[i] | 0x20) == b'e' {
        i += 1;
        let mut exponent_negative = false;
        if i < n && (s[i] == b'-' || s[i] == b'+') {
            exponent_negative = s[i] == b'-';
            i += 1;
        }
        let exponent_start = i;
        while i < n {
            let d = s[i].wrapping_sub(b'0');
            if d > 9 {
                break;
            }
            // Saturate: anything this large is out of every fast path anyway.
            if exponent < 1_000_000 {
                exponent = exponent * 10 + d as i64;
            }
            i += 1;
        }
        if i == exponent_start {
            return Err(token_end(s, i));
        }
        if exponent_negative {
            exponent = -exponent;
        }
    }
    if i < n && !is_separator(s[i]) {
        return Err(token_end(s, i));
    }
    if digits <= 19 {
        if let Some(v) = fast_path::<F>(m, exponent - fraction_digits as i64) {
            return Ok((v.with_sign(negative), i));
        }
    }
    slow_path(s, start, i)
}

/// The standard library's parser, for what the fast path cannot do exactly. The token
/// has been checked against the float syntax already, so it is ASCII and std accepts it.
#[cold]
#[inline(never)]
fn slow_path<F: Float>(s: &[u8], start: usize, end: usize) -> Result<(F, usize), usize> {
    match std::str::from_utf8(&s[start..end])
        .ok()
        .and_then(F::parse_std)
    {
        Some(v) => Ok((v, end)),
        None => Err(end),
    }
}

/// `[+-]?(inf|infinity|nan)`, any case.
#[cold]
#[inline(never)]
fn scan_special<F: Float>(s: &[u8], start: usize) -> Result<(F, usize), usize> {
    let end = token_end(s, start);
    let token = &s[start..end];
    let (negative, word) = match token.first() {
        Some(b'-') => (true, &token[1..]),
        Some(b'+') => (false, &token[1..]),
        _ => (false, token),
    };
    let value = if word.eq_ignore_ascii_case(b"inf") || word.eq_ignore_ascii_case(b"infinity") {
        F::INFINITY
    } else if word.eq_ignore_ascii_case(b"nan") {
        F::NAN
    } else {
        return Err(end);
    };
    Ok((if negative { value.neg() } else { value }, end))
}

/// Whole-token form of [`scan_float`].
#[inline]
fn parse_float<F: Float>(token: &[u8]) -> Option<F> {
    match scan_float::<F>(token, 0) {
        Ok((v, end)) if end == token.len() => Some(v),
        _ => None,
    }
}

/// Parses a whole token as a correctly rounded `f32` (decimal syntax, `INF`, `-INF`,
/// `NaN`, and Rust's `inf`/`infinity`/`nan` in any case). `None` when the token is not
/// exactly one number.
pub fn parse_f32(token: &[u8]) -> Option<f32> {
    parse_float(token)
}

/// Parses a whole token as a correctly rounded `f64`; see [`parse_f32`].
pub fn parse_f64(token: &[u8]) -> Option<f64> {
    parse_float(token)
}

/// An integer token that is not a valid value.
#[derive(Copy, Clone, Debug, PartialEq, Eq)]
pub enum IntError {
    /// Not an integer at all.
    Syntax,
    /// An integer outside the allowed range.
    OutOfRange,
}

/// Reads `[+-]?(digits|0[xX]hexdigits)` starting at `s[start]`; the token must end at a
/// separator or at the end of `s`. Returns the sign, the magnitude (saturated at
/// `u64::MAX`) and the end offset; on a syntax error, the offset where the token ends.
#[inline(always)]
fn scan_integer(s: &[u8], start: usize) -> Result<(bool, u64, usize), usize> {
    match scan_short_integer(s, start) {
        Some(short) => Ok(short),
        None => scan_integer_general(s, start),
    }
}

/// [`scan_integer`] for `[+-]?d{1,8}` followed by a separator (not at the end of the
/// text): the digits found and read in one word. `None` for anything else, which the
/// general scan then reads from the start.
#[inline(always)]
fn scan_short_integer(s: &[u8], start: usize) -> Option<(bool, u64, usize)> {
    let (negative, i) = scan_sign(s, start);
    let (word, bytes) = short_window(s, i)?;
    let digits = leading_digits(word) as usize;
    if digits == 0 || !is_separator(bytes[digits]) {
        return None;
    }
    Some((negative, digits_value(word, digits), i + digits))
}

/// [`scan_integer`] for any token.
#[inline(never)]
fn scan_integer_general(s: &[u8], start: usize) -> Result<(bool, u64, usize), usize> {
    let n = s.len();
    let (negative, mut i) = scan_sign(s, start);
    let mut magnitude: u64 = 0;
    let digits_start;
    if i + 1 < n && s[i] == b'0' && (s[i + 1] | 0x20) == b'x' {
        i += 2;
        digits_start = i;
        while i < n {
            let b = s[i];
            let d = match b {
                b'0'..=b'9' => b - b'0',
                b'a'..=b'f' => b - b'a' + 10,
                b'A'..=b'F' => b - b'A' + 10,
                _ => break,
            };
            magnitude = magnitude.saturating_mul(16).saturating_add(d as u64);
            i += 1;
        }
    } else {
        digits_start = i;
        // Leading zeros change nothing; after them, up to 19 digits fit in a u64 and
        // more saturate.
        while s.get(i) == Some(&b'0') {
            i += 1;
        }
        let significant = i;
        i = scan_digits(s, i, &mut magnitude);
        if i - significant > 19 {
            magnitude = u64::MAX;
        }
    }
    if i == digits_start || (i < n && !is_separator(s[i])) {
        return Err(token_end(s, i));
    }
    Ok((negative, magnitude, i))
}

/// Reads an `SFInt32` token (decimal or `0x` hexadecimal, optionally signed) starting at
/// `s[start]`. Returns the value and the end offset, or the error and the token's end.
#[inline(always)]
pub fn scan_i32(s: &[u8], start: usize) -> Result<(i32, usize), (IntError, usize)> {
    match scan_integer(s, start) {
        Ok((false, m, end)) if m <= i32::MAX as u64 => Ok((m as i32, end)),
        Ok((true, m, end)) if m <= 1 << 31 => Ok(((m as i64).wrapping_neg() as i32, end)),
        Ok((_, _, end)) => Err((IntError::OutOfRange, end)),
        Err(end) => Err((IntError::Syntax, end)),
    }
}

/// Reads an SFImage pixel value: like [`scan_i32`] but up to `0xFFFFFFFF` (4294967295);
/// negative values down to −2^31 are taken as their 32-bit two's complement pattern.
#[inline(always)]
pub fn scan_pixel(s: &[u8], start: usize) -> Result<(u32, usize), (IntError, usize)> {
    match scan_integer(s, start) {
        Ok((false, m, end)) if m <= u32::MAX as u64 => Ok((m as u32, end)),
        Ok((true, m, end)) if m <= 1 << 31 => Ok(((m as i64).wrapping_neg() as i32 as u32, end)),
        Ok((_, _, end)) => Err((IntError::OutOfRange, end)),
        Err(end) => Err((IntError::Syntax, end)),
    }
}

/// Parses a whole token as an `i32` (decimal or `0x` hexadecimal, optionally signed).
pub fn parse_i32(token: &[u8]) -> Option<i32> {
    match scan_i32(token, 0) {
        Ok((v, end)) if end == token.len() => Some(v),
        _ => None,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn f32_bits(s: &str) -> u32 {
        parse_f32(s.as_bytes())
            .unwrap_or_else(|| panic!("{s:?} did not parse"))
            .to_bits()
    }

    fn same_as_std_f32(s: &str) {
        let std: f32 = s.parse().unwrap();
        assert_eq!(f32_bits(s), std.to_bits(), "{s}");
    }

    fn same_as_std_f64(s: &str) {
        let std: f64 = s.parse().unwrap();
        let ours = parse_f64(s.as_bytes()).unwrap_or_else(|| panic!("{s:?} did not parse"));
        assert_eq!(ours.to_bits(), std.to_bits(), "{s}");
    }

    #[test]
    fn simple_values() {
        assert_eq!(parse_f32(b"1"), Some(1.0));
        assert_eq!(parse_f32(b"-12.3456"), Some(-12.3456));
        assert_eq!(parse_f32(b".5"), Some(0.5));
        assert_eq!(parse_f32(b"5."), Some(5.0));
        assert_eq!(parse_f32(b"+5"), Some(5.0));
        assert_eq!(parse_f32(b"1.e2"), Some(100.0));
        assert_eq!(parse_f32(b"1E-2"), Some(0.01));
        assert_eq!(parse_f32(b"2.5e+3"), Some(2500.0));
        assert_eq!(parse_f64(b"0.1"), Some(0.1));
        assert_eq!(parse_f64(b"-1e22"), Some(-1e22));
        assert_eq!(parse_f64(b"123456789012345678"), Some(123456789012345678.0));
    }

    #[test]
    fn rejects_bad_syntax() {
        for bad in [
            "", "+", "-", ".", "e5", ".e5", "1e", "1e+", "1.2.3", "1x", "0x10", "1_0", " 1", "1 ",
            "--1", "1e5.5", "abc", "nanx", "in", "1,", "é", "1é",
        ] {
            assert_eq!(parse_f32(bad.as_bytes()), None, "{bad:?}");
            assert_eq!(parse_f64(bad.as_bytes()), None, "{bad:?}");
        }
    }

    #[test]
    fn special_tokens() {
        assert!(parse_f32(b"NaN").unwrap().is_nan());
        assert!(parse_f32(b"nan").unwrap().is_nan());
        assert!(parse_f64(b"NAN").unwrap().is_nan());
        assert_eq!(parse_f32(b"INF"), Some(f32::INFINITY));
        assert_eq!(parse_f32(b"-INF"), Some(f32::NEG_INFINITY));
        assert_eq!(parse_f32(b"+inf"), Some(f32::INFINITY));
        assert_eq!(parse_f32(b"Infinity"), Some(f32::INFINITY));
        assert_eq!(parse_f64(b"-infinity"), Some(f64::NEG_INFINITY));
    }

    #[test]
    fn signed_zero() {
        assert_eq!(f32_bits("-0"), (-0.0f32).to_bits());
        assert_eq!(f32_bits("-0.0"), (-0.0f32).to_bits());
        assert_eq!(f32_bits("-0e999"), (-0.0f32).to_bits());
        assert_eq!(f32_bits("0"), 0);
        assert_eq!(parse_f64(b"-0").unwrap().to_bits(), (-0.0f64).to_bits());
        assert_eq!(
            parse_f64(b"-0.00000000000000000000000").unwrap().to_bits(),
            (-0.0f64).to_bits()
        );
    }

    #[test]
    fn f32_extremes() {
        assert_eq!(parse_f32(b"3.4028235e38"), Some(f32::MAX));
        // The midpoint between f32::MAX and 2^128 is 3.40282356779733661637…e38: anything
        // at or above it rounds to infinity, so 3.4028236e38 is infinite.
        assert_eq!(parse_f32(b"3.4028236e38"), Some(f32::INFINITY));
        same_as_std_f32("3.4028236e38");
        assert_eq!(parse_f32(b"3.4028235677973366e38"), Some(f32::MAX));
        assert_eq!(parse_f32(b"3.4028235677973367e38"), Some(f32::INFINITY));
        assert_eq!(parse_f32(b"1e39"), Some(f32::INFINITY));
        assert_eq!(parse_f32(b"-1e39"), Some(f32::NEG_INFINITY));
        assert_eq!(parse_f32(b"1e-46"), Some(0.0));
        // Smallest denormal and the rounding around half of it.
        assert_eq!(parse_f32(b"1.401298464324817e-45"), Some(f32::from_bits(1)));
        assert_eq!(parse_f32(b"7.1e-46"), Some(f32::from_bits(1)));
        assert_eq!(parse_f32(b"7e-46"), Some(0.0));
        same_as_std_f32("1e-40");
        assert!(parse_f32(b"1e-40").unwrap().is_subnormal());
        assert_eq!(parse_f32(b"1.17549435e-38"), Some(f32::MIN_POSITIVE));
        assert_eq!(parse_f64(b"1.7976931348623157e308"), Some(f64::MAX));
        assert_eq!(parse_f64(b"1e309"), Some(f64::INFINITY));
        assert_eq!(parse_f64(b"5e-324"), Some(f64::from_bits(1)));
        assert_eq!(parse_f64(b"1e-400"), Some(0.0));
        assert_eq!(parse_f32(b"1e99999999999999999999"), Some(f32::INFINITY));
        assert_eq!(parse_f32(b"1e-99999999999999999999"), Some(0.0));
    }

    #[test]
    fn no_double_rounding() {
        // Exactly halfway between two f32 values, but not representable in f64 after
        // a few more digits: converting through f64 would round twice.
        // 1 + 2^-24 is the midpoint between 1 and 1 + 2^-23; ties go to even (1.0).
        same_as_std_f32("1.000000059604644775390625");
        assert_eq!(parse_f32(b"1.000000059604644775390625"), Some(1.0));
        // A hair above the midpoint rounds up, though through f64 it would be 1 + 2^-24
        // exactly and then round down to 1.0.
        let above = "1.00000005960464477539062500000000001";
        assert_eq!(parse_f32(above.as_bytes()), Some(1.0 + f32::EPSILON));
        same_as_std_f32(above);
        same_as_std_f32("8.589973e9");
        // Within half an f64 ulp of that midpoint: rounds to it in f64, so a naive
        // conversion through f64 would then round to even (1.0). The exact value is above
        // the midpoint, so the answer is 1 + 2^-23; and just below it, 1.0.
        assert_eq!(parse_f32(b"1.0000000596046448"), Some(1.0 + f32::EPSILON));
        same_as_std_f32("1.0000000596046448");
        assert_eq!(parse_f32(b"1.0000000596046447"), Some(1.0));
        same_as_std_f32("1.0000000596046447");
        same_as_std_f32("0.10000000596046448e1");
        same_as_std_f32("10000000596046448e-16");
        same_as_std_f32("0.1");
        same_as_std_f32("16777217");
        same_as_std_f32("16777217.0");
        same_as_std_f64("9007199254740993");
        same_as_std_f64("2.2250738585072011e-308");
    }

    #[test]
    fn fast_path_edges() {
        for s in [
            "16777216",
            "16777217",
            "1677721.6",
            "0.500000000000",
            "5000000000000000000000",
            "3e12",
            "3e17",
            "3e18",
            "12345678e10",
            "1234567e-10",
            "1e10",
            "1e11",
            "1e-10",
            "1e-11",
            "99999999999999999999",
            "0.000000000000000000001",
            "1000000000000000000000000000000e-30",
            "4.2949673e9",
            "123.456789",
        ] {
            same_as_std_f32(s);
            same_as_std_f64(s);
        }
        for s in [
            "9007199254740992",
            "9007199254740993e5",
            "1e22",
            "1e23",
            "3e30",
            "1.5e-22",
        ] {
            same_as_std_f64(s);
        }
    }

    #[test]
    fn very_long_tokens() {
        let long = "1".repeat(10_000);
        assert_eq!(parse_f32(long.as_bytes()), Some(f32::INFINITY));
        assert_eq!(parse_f64(long.as_bytes()), Some(f64::INFINITY));
        let small = format!("0.{}1", "0".repeat(10_000));
        assert_eq!(parse_f32(small.as_bytes()), Some(0.0));
        let one = format!("1.{}", "0".repeat(10_000));
        assert_eq!(parse_f32(one.as_bytes()), Some(1.0));
        let fraction = format!("0.{}", "3".repeat(10_000));
        same_as_std_f32(&fraction);
        same_as_std_f64(&fraction);
    }

    #[test]
    fn scanning_within_text() {
        let s = b"1.5, -2 3e1\t.25";
        let (a, e) = scan_float::<f32>(s, 0).unwrap();
        assert_eq!((a, e), (1.5, 3));
        let (b, e) = scan_float::<f32>(s, 5).unwrap();
        assert_eq!((b, e), (-2.0, 7));
        let (c, e) = scan_float::<f32>(s, 8).unwrap();
        assert_eq!((c, e), (30.0, 11));
        let (d, e) = scan_float::<f32>(s, 12).unwrap();
        assert_eq!((d, e), (0.25, 15));
        assert_eq!(scan_float::<f32>(b"1.2.3 4", 0), Err(5));
        assert_eq!(scan_float::<f32>(b"true 4", 0), Err(4));
    }

    /// A small deterministic generator of digit strings (xorshift).
    struct Digits(u64);

    impl Digits {
        fn take(&mut self, n: usize) -> String {
            (0..n)
                .map(|_| {
                    self.0 ^= self.0 << 13;
                    self.0 ^= self.0 >> 7;
                    self.0 ^= self.0 << 17;
                    char::from(b'0' + (self.0 % 10) as u8)
                })
                .collect()
        }
    }

    /// What may follow a token: separators, and bytes that make it something else.
    const AFTER_TOKEN: [&str; 9] = [" ", ",", "\t", "\n", "\r", "e5", "E-1", "x", "/"];

    /// The short path takes every token of its shape (up to eight bytes of digits and one
    /// `.` after the sign, then a separator) and reads it as the general scan and the
    /// standard library do, at every length up to and past eight bytes; it leaves every
    /// other token to the general scan.
    #[test]
    fn short_decimals_agree_with_the_general_scan() {
        let mut random = Digits(0x2545_f491_4f6c_dd1d);
        let mut taken = 0;
        for int_digits in 0..=9 {
            for fraction in [None, Some(0), Some(1), Some(4), Some(7), Some(8), Some(9)] {
                for sign in ["", "-", "+"] {
                    for after in AFTER_TOKEN {
                        for _ in 0..20 {
                            let mut token = format!("{sign}{}", random.take(int_digits));
                            if let Some(n) = fraction {
                                token = format!("{token}.{}", random.take(n));
                            }
                            let text = format!("{token}{after} 1 2 3 4 5 6 7 8");
                            let bytes = text.as_bytes();
                            let short = scan_short_decimal::<f32>(bytes, 0);
                            let short64 = scan_short_decimal::<f64>(bytes, 0);
                            let digits = int_digits + fraction.unwrap_or(0);
                            let unsigned = token.len() - sign.len();
                            let separated = is_separator(after.as_bytes()[0]);
                            if digits > 0 && unsigned <= 8 && separated {
                                // Up to seven digits every f32 fast path is exact; up to
                                // eight the f64 one.
                                assert!(short.is_some() || digits == 8, "{text:?}");
                                assert!(short64.is_some(), "{text:?}");
                                taken += 1;
                            } else {
                                assert_eq!(short, None, "{text:?}");
                                assert_eq!(short64, None, "{text:?}");
                            }
                            if let Some((v, end)) = short {
                                let general = scan_float_general::<f32>(bytes, 0);
                                assert_eq!(
                                    general.map(|(v, e)| (v.to_bits(), e)),
                                    Ok((v.to_bits(), end))
                                );
                                assert_eq!(end, token.len(), "{text:?}");
                                same_as_std_f32(&token);
                            }
                            if let Some((v, end)) = short64 {
                                let general = scan_float_general::<f64>(bytes, 0);
                                assert_eq!(
                                    general.map(|(v, e)| (v.to_bits(), e)),
                                    Ok((v.to_bits(), end))
                                );
                                same_as_std_f64(&token);
                            }
                        }
                    }
                }
            }
        }
        assert!(taken > 5_000, "{taken}");
    }

    #[test]
    fn short_decimals_at_the_edges() {
        for token in [
            "0", "-0", "-0.0", ".5", "5.", "-.5", "00000000", "99999999", "9999999.", ".9999999",
            "0.600025", "16777217", "16777.21", "9.999999", "0.000001",
        ] {
            let text = format!("{token} 1 2 3 4 5");
            let (v, end) = scan_short_decimal::<f32>(text.as_bytes(), 0)
                .or_else(|| scan_float_general(text.as_bytes(), 0).ok())
                .unwrap();
            assert_eq!(end, token.len());
            assert_eq!(
                v.to_bits(),
                token.parse::<f32>().unwrap().to_bits(),
                "{token}"
            );
            let (v, _) = scan_short_decimal::<f64>(text.as_bytes(), 0).expect(token);
            assert_eq!(
                v.to_bits(),
                token.parse::<f64>().unwrap().to_bits(),
                "{token}"
            );
        }
        assert_eq!(
            scan_short_decimal::<f32>(b"-0 1 2 3 4 5", 0)
                .unwrap()
                .0
                .to_bits(),
            (-0.0f32).to_bits()
        );
        // Too near the end of the text for a window: the general scan's.
        assert_eq!(scan_short_decimal::<f32>(b"1.5 2 3", 0), None);
        assert_eq!(scan_float::<f32>(b"1.5 2 3", 0), Ok((1.5, 3)));
    }

    /// As for decimals: `[+-]?d{1,8}` then a separator is the short path's, read as the
    /// general scan reads it; anything else is left to the general scan.
    #[test]
    fn short_integers_agree_with_the_general_scan() {
        let mut random = Digits(0x9e37_79b9_7f4a_7c15);
        for digits in 0..=10 {
            for sign in ["", "-", "+"] {
                for after in AFTER_TOKEN {
                    for _ in 0..20 {
                        let token = format!("{sign}{}", random.take(digits));
                        let text = format!("{token}{after} 1 2 3 4 5 6 7 8");
                        let bytes = text.as_bytes();
                        let short = scan_short_integer(bytes, 0);
                        if digits > 0 && digits <= 8 && is_separator(after.as_bytes()[0]) {
                            assert_eq!(short, scan_integer_general(bytes, 0).ok(), "{text:?}");
                            assert_eq!(short.map(|(_, _, end)| end), Some(token.len()));
                        } else {
                            assert_eq!(short, None, "{text:?}");
                        }
                    }
                }
            }
        }
        assert_eq!(scan_short_integer(b"0x1F 1 2 3 4 5", 0), None);
        assert_eq!(scan_i32(b"0x1F 1 2 3 4 5", 0), Ok((31, 4)));
        assert_eq!(scan_i32(b"-00000007 1 2 3 4", 0), Ok((-7, 9)));
    }

    #[test]
    fn integers() {
        assert_eq!(parse_i32(b"0"), Some(0));
        assert_eq!(parse_i32(b"-0"), Some(0));
        assert_eq!(parse_i32(b"+17"), Some(17));
        assert_eq!(parse_i32(b"007"), Some(7));
        assert_eq!(parse_i32(b"2147483647"), Some(i32::MAX));
        assert_eq!(parse_i32(b"-2147483648"), Some(i32::MIN));
        assert_eq!(parse_i32(b"2147483648"), None);
        assert_eq!(parse_i32(b"-2147483649"), None);
        assert_eq!(parse_i32(b"0xFF"), Some(255));
        assert_eq!(parse_i32(b"0Xff"), Some(255));
        assert_eq!(parse_i32(b"-0x10"), Some(-16));
        assert_eq!(parse_i32(b"0x7FFFFFFF"), Some(i32::MAX));
        assert_eq!(parse_i32(b"0x80000000"), None);
        assert_eq!(parse_i32(b"0x"), None);
        assert_eq!(parse_i32(b"0xG"), None);
        assert_eq!(parse_i32(b"1.5"), None);
        assert_eq!(parse_i32(b"1e3"), None);
        assert_eq!(parse_i32(b""), None);
        assert_eq!(parse_i32(b"-"), None);
        assert_eq!(parse_i32("9".repeat(10_000).as_bytes()), None);
        // Leading zeros, then digits read eight at a time: 2^64 would wrap to 0.
        assert_eq!(parse_i32(b"000000000000000000000000042"), Some(42));
        assert_eq!(
            parse_i32(b"-0000000000000000000002147483648"),
            Some(i32::MIN)
        );
        assert_eq!(parse_i32(b"18446744073709551616"), None);
        assert_eq!(parse_i32(b"9999999999999999999"), None);
        assert_eq!(
            scan_i32(b"99999999999 1", 0),
            Err((IntError::OutOfRange, 11))
        );
        assert_eq!(scan_i32(b"1.5 1", 0), Err((IntError::Syntax, 3)));
    }

    #[test]
    fn pixels() {
        assert_eq!(scan_pixel(b"0xFFFFFFFF", 0), Ok((u32::MAX, 10)));
        assert_eq!(scan_pixel(b"4294967295", 0), Ok((u32::MAX, 10)));
        assert_eq!(scan_pixel(b"-1", 0), Ok((u32::MAX, 2)));
        assert_eq!(scan_pixel(b"-2147483648", 0), Ok((0x8000_0000, 11)));
        assert_eq!(
            scan_pixel(b"4294967296", 0),
            Err((IntError::OutOfRange, 10))
        );
        assert_eq!(
            scan_pixel(b"0x100000000", 0),
            Err((IntError::OutOfRange, 11))
        );
        assert_eq!(
            scan_pixel(b"-2147483649", 0),
            Err((IntError::OutOfRange, 11))
        );
    }
}
