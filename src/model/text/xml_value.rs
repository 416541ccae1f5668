//! Field values in the XML encoding (ISO/IEC 19776-1 clause 5): the text of an attribute,
//! already unescaped by the XML reader, turned into a typed [`Value`].
//!
//! Values are separated by XML whitespace. A comma counts as whitespace only where 19776-1
//! 5.1.2 allows one: between the values of an MF field (after a whole SFVec3f of an
//! MFVec3f, after any number of an MFFloat); elsewhere (`diffuseColor='1,0,0'`) it is an
//! error that still reads as whitespace, as browsers read it. Numbers go straight into one
//! flat vector per field, with no allocation per number. Non-finite and overflowing floats
//! are kept as NaN and ±infinity: reporting them is a rule's job, as is comparing an
//! image's pixel count with its size.

use std::fmt;
use std::ops::Range;

use rayon::prelude::*;

use super::number::{is_separator, scan_float, scan_i32, scan_pixel, token_end, Float, IntError};
use super::{huge_vec, split};
use crate::model::{Image, Node, Sink, Summarized, Summarizer, Value};
use crate::schema::{FieldDef, FieldType, Scalar};

/// A value that does not follow the syntax of its field type. `offset` and `len` are a
/// byte range in the text given to [`parse_value`].
#[derive(Clone, Debug, PartialEq)]
pub struct SyntaxError {
    pub offset: usize,
    pub len: usize,
    pub message: String,
    /// How to write the value instead, where one rewrite fixes it (`"SANS"` for `SANS`).
    pub fix: Option<String>,
    /// What the value looks like, where no rewrite is sure to keep its meaning.
    pub help: Option<String>,
    /// The value browsers read despite the error, where there is no doubt about it (a
    /// misplaced comma read as whitespace, an unquoted MFString read as one string), so
    /// that the rules after the reader judge what is drawn rather than the default.
    pub recovered: Option<Box<Value>>,
}

impl SyntaxError {
    fn new(offset: usize, len: usize, message: impl Into<String>) -> SyntaxError {
        SyntaxError {
            offset,
            len,
            message: message.into(),
            fix: None,
            help: None,
            recovered: None,
        }
    }

    fn recovering(mut self, value: Value) -> SyntaxError {
        self.recovered = Some(Box::new(value));
        self
    }

    /// The value as browsers read it, if the error leaves no doubt about it.
    pub fn into_recovered(self) -> Option<Value> {
        self.recovered.map(|v| *v)
    }

    fn at(range: (usize, usize), message: impl Into<String>) -> SyntaxError {
        SyntaxError::new(range.0, range.1 - range.0, message)
    }
}

impl fmt::Display for SyntaxError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.message)
    }
}

impl std::error::Error for SyntaxError {}

/// Parses the text of an attribute as a value of type `ty`.
///
/// `text` is the attribute value after XML entity unescaping. Offsets in the error are byte
/// offsets into `text`. SFNode and MFNode values are child elements, not attribute text,
/// so they are always an error here.
pub fn parse_value(ty: FieldType, text: &str) -> Result<Value, SyntaxError> {
    parse_value_in(Syntax::Xml, ty, text)
}

/// Where a value's text comes from: the two encodings write numbers alike (ClassicVRML
/// numbers are separated by the same whitespace and commas, 19776-2 5.1) and differ in
/// booleans and strings.
#[derive(Copy, Clone, Debug, PartialEq, Eq)]
pub enum Syntax {
    /// An XML attribute (19776-1 5): `true`/`false`; an SFString is the text itself.
    Xml,
    /// The text between a ClassicVRML field's brackets, or its single value (19776-2 5):
    /// `TRUE`/`FALSE`; every string, SFString too, is double-quoted with `\"` and `\\`
    /// escapes.
    Classic,
}

/// [`parse_value`] for text in the given [`Syntax`].
pub fn parse_value_in(syntax: Syntax, ty: FieldType, text: &str) -> Result<Value, SyntaxError> {
    parse_value_split(syntax, ty, text, Split::Auto)
}

/// [`parse_value_in`] with a numeric MF value cut into pieces of about `piece` bytes,
/// whatever its length and the number of threads: for the tests that pin that parsing in
/// pieces gives what parsing in one piece does.
#[doc(hidden)]
pub fn parse_value_in_pieces(
    syntax: Syntax,
    ty: FieldType,
    text: &str,
    piece: usize,
) -> Result<Value, SyntaxError> {
    parse_value_split(syntax, ty, text, Split::Pieces(piece))
}

/// Whether and how a long numeric value is cut into pieces parsed on several threads.
#[derive(Copy, Clone, Debug)]
enum Split {
    /// As [`split::piece_size`] says for its length and the current pool.
    Auto,
    /// In pieces of about this many bytes.
    Pieces(usize),
}

fn parse_value_split(
    syntax: Syntax,
    ty: FieldType,
    text: &str,
    split: Split,
) -> Result<Value, SyntaxError> {
    let s = text.as_bytes();
    let (value, comma) = match ty.scalar() {
        Scalar::Float => {
            let (values, comma) = parse_numbers::<f32>(ty, s, split)?;
            check_count(ty, s, values.len())?;
            (Value::Floats(values), comma)
        }
        Scalar::Double => {
            let (values, comma) = parse_numbers::<f64>(ty, s, split)?;
            check_count(ty, s, values.len())?;
            (Value::Doubles(values), comma)
        }
        Scalar::Int32 => {
            let (values, comma) = parse_numbers::<i32>(ty, s, split)?;
            check_count(ty, s, values.len())?;
            (Value::Int32s(values), comma)
        }
        Scalar::Bool => {
            let (values, comma) = parse_bools(syntax, ty, s)?;
            check_count(ty, s, values.len())?;
            (Value::Bools(values), comma)
        }
        Scalar::String if syntax == Syntax::Classic => {
            return parse_quoted(ty, text).map(Value::Strings)
        }
        Scalar::String if ty.is_mf() => return parse_mfstring(text).map(Value::Strings),
        Scalar::String => return Ok(Value::Strings(vec![text.to_owned()])),
        Scalar::Image => {
            let (images, comma) = parse_images(ty, s)?;
            (Value::Images(images), comma)
        }
        Scalar::Node => {
            return Err(SyntaxError::new(
                0,
                text.len(),
                format!("{ty} fields take child elements, not attribute text"),
            ))
        }
    };
    // ClassicVRML reads commas as white space (19776-2 5.1); XML allows them only
    // between MF elements (19776-1 5.1.2).
    match comma {
        Some(at) if syntax == Syntax::Xml => Err(comma_error(ty, s, at).recovering(value)),
        _ => Ok(value),
    }
}

/// [`parse_value`] for the schema field `def` of `node`, a numeric MF field
/// ([`Summary::applies_to`](crate::model::Summary::applies_to)), keeping a
/// [`Summary`](crate::model::Summary) instead of its numbers (the fast
/// level): the same numbers are parsed, the same errors reported, and the summary says
/// what the fast-level rules would find.
pub fn parse_summary(
    node: &Node,
    def: &'static FieldDef,
    text: &str,
) -> Result<Value, SyntaxError> {
    match def.ty.scalar() {
        Scalar::Float => summarize::<f32>(node, def, text.as_bytes()),
        Scalar::Double => summarize::<f64>(node, def, text.as_bytes()),
        _ => summarize::<i32>(node, def, text.as_bytes()),
    }
}

/// The numbers of `s` into a summary.
fn summarize<T: Summarized + Numeric>(
    node: &Node,
    def: &'static FieldDef,
    s: &[u8],
) -> Result<Value, SyntaxError> {
    let mut summarizer = Summarizer::<T>::new(node, def);
    let comma = scan_numbers(def.ty, s, &mut summarizer, Split::Auto)?;
    check_count(def.ty, s, summarizer.count())?;
    match comma {
        None => Ok(summarizer.finish()),
        Some(at) => Err(comma_error(def.ty, s, at).recovering(summarizer.finish())),
    }
}

/// Capacity for the numbers in `s`: a guess from its length (at least two bytes per
/// number, usually many more), so that big values grow their vector rarely.
fn estimate(s: &[u8]) -> usize {
    s.len() / 4 + 1
}

/// Drops the excess capacity a generous estimate left behind.
fn trim_capacity<T>(v: &mut Vec<T>) {
    if v.capacity() > v.len() + v.len() / 4 + 16 {
        v.shrink_to_fit();
    }
}

/// `(start, end)` of every token; for error paths only.
fn tokens(s: &[u8]) -> impl Iterator<Item = (usize, usize)> + '_ {
    let mut i = 0;
    std::iter::from_fn(move || {
        while i < s.len() && is_separator(s[i]) {
            i += 1;
        }
        if i >= s.len() {
            return None;
        }
        let start = i;
        i = token_end(s, i);
        Some((start, i))
    })
}

/// The token for an error message, shortened when long.
fn show(s: &[u8], start: usize, end: usize) -> String {
    let text = String::from_utf8_lossy(&s[start..end]);
    const MAX: usize = 40;
    if text.chars().count() > MAX {
        let short: String = text.chars().take(MAX).collect();
        format!("{short}…")
    } else {
        text.into_owned()
    }
}

fn trim_xml_whitespace(text: &str) -> &str {
    text.trim_matches(|c| matches!(c, ' ' | '\t' | '\n' | '\r'))
}

fn plural(n: usize, one: &str, many: &str) -> String {
    if n == 1 {
        format!("1 {one}")
    } else {
        format!("{n} {many}")
    }
}

/// Checks the number of scalars against the type: exactly its arity for SF types, a
/// multiple of it for MF types.
fn check_count(ty: FieldType, s: &[u8], count: usize) -> Result<(), SyntaxError> {
    let arity = ty.arity();
    let what = match ty.scalar() {
        Scalar::Bool => ("value", "values"),
        _ => ("number", "numbers"),
    };
    if ty.is_mf() {
        if count.is_multiple_of(arity) {
            return Ok(());
        }
        // Point at the incomplete last element.
        let first = count - count % arity;
        let spans: Vec<(usize, usize)> = tokens(s).skip(first).collect();
        let start = spans.first().map_or(s.len(), |t| t.0);
        let end = spans.last().map_or(s.len(), |t| t.1);
        return Err(SyntaxError::at(
            (start, end),
            format!("{ty} takes a multiple of {arity} {}, found {count}", what.1),
        ));
    }
    if count == arity {
        return Ok(());
    }
    let expected = plural(arity, what.0, what.1);
    if count == 0 {
        // Only separators: point at all of it.
        return Err(SyntaxError::new(
            0,
            s.len(),
            format!("{ty} takes {expected}, found none"),
        ));
    }
    let range = if count > arity {
        // Point at the surplus.
        let mut surplus = tokens(s).skip(arity);
        let start = surplus.next().map_or(s.len(), |t| t.0);
        let end = surplus.last().map_or_else(|| token_end(s, start), |t| t.1);
        (start, end)
    } else {
        let mut all = tokens(s);
        let start = all.next().map_or(0, |t| t.0);
        let end = all.last().map_or_else(|| token_end(s, start), |t| t.1);
        (start, end)
    };
    Err(SyntaxError::at(
        range,
        format!("{ty} takes {expected}, found {count}"),
    ))
}

/// The numbers of `s`, with the offset of the first comma 19776-1 5.1.2 does not allow.
type Scanned<T> = (Vec<T>, Option<usize>);

fn parse_numbers<T: Numeric>(
    ty: FieldType,
    s: &[u8],
    split: Split,
) -> Result<Scanned<T>, SyntaxError> {
    let mut values: Vec<T> = if ty.is_mf() {
        huge_vec::with_capacity(estimate(s))
    } else {
        Vec::with_capacity(ty.arity())
    };
    let comma = scan_numbers(ty, s, &mut values, split)?;
    trim_capacity(&mut values);
    Ok((values, comma))
}

/// A numeric scalar type with its one-piece scanner.
trait Numeric: Copy + Send + 'static {
    /// The numbers of `s` into `values`; the offset of the first misplaced comma.
    fn scan<S: Sink<Self>>(
        ty: FieldType,
        s: &[u8],
        values: &mut S,
    ) -> Result<Option<usize>, SyntaxError>;
}

impl Numeric for f32 {
    fn scan<S: Sink<f32>>(
        ty: FieldType,
        s: &[u8],
        values: &mut S,
    ) -> Result<Option<usize>, SyntaxError> {
        scan_floats(ty, s, values)
    }
}

impl Numeric for f64 {
    fn scan<S: Sink<f64>>(
        ty: FieldType,
        s: &[u8],
        values: &mut S,
    ) -> Result<Option<usize>, SyntaxError> {
        scan_floats(ty, s, values)
    }
}

impl Numeric for i32 {
    fn scan<S: Sink<i32>>(
        ty: FieldType,
        s: &[u8],
        values: &mut S,
    ) -> Result<Option<usize>, SyntaxError> {
        scan_int32s(ty, s, values)
    }
}

/// [`Numeric::scan`], in pieces on several threads when an MF value is long
/// ([`split`]). The numbers, the error and the misplaced comma are those of the one-piece
/// scan: the first piece with an error has the first error, and commas are judged once
/// the count before each piece is known.
fn scan_numbers<T: Numeric, S: Sink<T> + Send>(
    ty: FieldType,
    s: &[u8],
    values: &mut S,
    split: Split,
) -> Result<Option<usize>, SyntaxError> {
    let piece = match split {
        Split::Auto => split::piece_size(s.len(), rayon::current_num_threads),
        Split::Pieces(bytes) => Some(bytes),
    };
    let Some(piece) = piece.filter(|_| ty.is_mf()) else {
        return T::scan(ty, s, values);
    };
    let counted = split::scan_pieces(
        s,
        piece,
        values,
        |range, values| scan_piece(ty, s, range, values),
        |range, values| scan_piece(ty, s, range, values),
    )?;
    if memchr::memchr(b',', s).is_none() {
        return Ok(None);
    }
    Ok(counted
        .into_par_iter()
        .find_map_first(|(range, before)| first_misplaced_comma(ty, s, range, before)))
}

/// The numbers of the tokens in `s[range]`, with errors placed in `s`; commas are judged
/// by [`first_misplaced_comma`].
fn scan_piece<T: Numeric, S: Sink<T>>(
    ty: FieldType,
    s: &[u8],
    range: Range<usize>,
    values: &mut S,
) -> Result<(), SyntaxError> {
    let start = range.start;
    match T::scan(ty, &s[range], values) {
        Ok(_) => Ok(()),
        Err(mut error) => {
            error.offset += start;
            Err(error)
        }
    }
}

/// The first comma in `s[range]` that [`comma_allowed`] refuses, `before` scalars
/// preceding the range: what the one-piece scan notes as it goes.
fn first_misplaced_comma(
    ty: FieldType,
    s: &[u8],
    range: Range<usize>,
    before: usize,
) -> Option<usize> {
    memchr::memchr(b',', &s[range.clone()])?;
    let s = &s[..range.end];
    let mut comma = None;
    let mut count = before;
    let mut i = range.start;
    loop {
        i = skip_separators(ty, s, i, count, &mut comma);
        if comma.is_some() || i >= s.len() {
            return comma;
        }
        i = token_end(s, i);
        count += 1;
    }
}

/// Whether a comma may follow `count` scalars of a value of type `ty`: only between the
/// values of an MF field, that is after a whole number of its elements (19776-1 5.1.2:
/// "commas may only be used as whitespace between values of individual base datatypes").
#[inline]
fn comma_allowed(ty: FieldType, count: usize) -> bool {
    ty.is_mf() && count > 0 && count.is_multiple_of(ty.arity())
}

/// Skips the separators from `i`; notes in `comma` the first comma that `comma_allowed`
/// refuses after `count` scalars.
#[inline(always)]
fn skip_separators(
    ty: FieldType,
    s: &[u8],
    mut i: usize,
    count: usize,
    comma: &mut Option<usize>,
) -> usize {
    while i < s.len() && is_separator(s[i]) {
        if s[i] == b',' && comma.is_none() && !comma_allowed(ty, count) {
            *comma = Some(i);
        }
        i += 1;
    }
    i
}

/// Skips white space from `i`, in a value known to hold no comma: most values, scanned
/// without [`skip_separators`]' per-byte comma test.
#[inline(always)]
fn skip_whitespace(s: &[u8], mut i: usize) -> usize {
    while i < s.len() && is_separator(s[i]) {
        i += 1;
    }
    i
}

/// The numbers of `s` into `values`; the offset of the first misplaced comma.
fn scan_floats<F: Float, S: Sink<F>>(
    ty: FieldType,
    s: &[u8],
    values: &mut S,
) -> Result<Option<usize>, SyntaxError> {
    let n = s.len();
    let mut i = 0;
    let mut comma = None;
    let has_comma = memchr::memchr(b',', s).is_some();
    loop {
        i = if has_comma {
            skip_separators(ty, s, i, values.count(), &mut comma)
        } else {
            skip_whitespace(s, i)
        };
        if i >= n {
            break;
        }
        match scan_float::<F>(s, i) {
            Ok((v, end)) => {
                values.push(v);
                // The token ends at a separator or at the end: where commas need no
                // judging, the next look can start after it.
                i = end + !has_comma as usize;
            }
            Err(end) => return Err(float_error(ty, s, i, end)),
        }
    }
    Ok(comma)
}

/// A comma where 19776-1 5.1.2 allows none, at `at`: inside an SF value, inside one
/// element of an MF value, or before its first value. The fix writes the value with spaces
/// between the numbers of an element and commas between elements, unless the commas group
/// the numbers in another size: then the help says so, and there is no fix.
#[cold]
fn comma_error(ty: FieldType, s: &[u8], at: usize) -> SyntaxError {
    let single = ty.single();
    let arity = ty.arity();
    if let Some((size, other)) = other_grouping(ty, s) {
        // The commas set the numbers apart in groups of another size: the author likely
        // wrote another type's values (x y w triples in an MFVec2d), and regrouping them
        // in the field's size would change what they mean, so there is no rewrite.
        let mut error = SyntaxError::new(
            at,
            1,
            format!(
                "commas after every {size} numbers, but each {single} of an {ty} has {arity}: commas may only separate whole {single} values"
            ),
        );
        error.help = Some(match other {
            Some(other) => format!("{size} numbers between commas: is this an {other}'s value?"),
            None => format!(
                "{size} numbers between commas: browsers read the numbers {arity} at a time, ignoring the commas"
            ),
        });
        return error;
    }
    let message = if !ty.is_mf() {
        format!("a comma inside an {ty}: commas may only separate the values of an MF field")
    } else if ty.scalar() == Scalar::Image {
        format!("a comma inside an image of an {ty}: commas may only separate whole images")
    } else if arity > 1 {
        let example: Vec<String> = [1, arity + 1]
            .iter()
            .map(|first| {
                let numbers: Vec<String> = (*first..first + arity).map(|k| k.to_string()).collect();
                numbers.join(" ")
            })
            .collect();
        format!(
            "a comma inside an {single} of an {ty}: commas may only separate whole {single} values (after every {arity} numbers), as in `{}`",
            example.join(", ")
        )
    } else {
        format!("a comma before the first value: commas may only separate the values of an {ty}")
    };
    let mut error = SyntaxError::new(at, 1, message);
    // A rewrite of a long value helps nobody; the message says what to change.
    if s.len() <= 200 {
        let spans: Vec<(usize, usize)> = tokens(s).collect();
        let words: Vec<String> = spans
            .iter()
            .map(|&(a, b)| String::from_utf8_lossy(&s[a..b]).into_owned())
            .collect();
        let group = if ty.is_mf() && ty.scalar() != Scalar::Image {
            arity
        } else {
            words.len().max(1)
        };
        let elements: Vec<String> = words.chunks(group).map(|c| c.join(" ")).collect();
        error.fix = Some(elements.join(", "));
    }
    error
}

/// The size of every group of numbers the commas of `s` set apart, where they all have
/// one size other than the arity of `ty` (a trailing comma allowed), and the MF type whose
/// values have that size, if there is one of the same precision.
fn other_grouping(ty: FieldType, s: &[u8]) -> Option<(usize, Option<FieldType>)> {
    if !ty.is_mf() || ty.arity() < 2 || ty.scalar() == Scalar::Image {
        return None;
    }
    let mut groups: Vec<usize> = s.split(|&b| b == b',').map(|g| tokens(g).count()).collect();
    if groups.len() > 1 && groups.last() == Some(&0) {
        groups.pop();
    }
    let size = *groups.first()?;
    if size < 2 || size == ty.arity() || groups.iter().any(|&g| g != size) {
        return None;
    }
    let other = FieldType::ALL
        .iter()
        .copied()
        .find(|t| t.is_mf() && t.scalar() == ty.scalar() && t.arity() == size);
    Some((size, other))
}

#[cold]
fn float_error(ty: FieldType, s: &[u8], start: usize, end: usize) -> SyntaxError {
    // The scanner may stop inside a token; report the whole of it.
    let mut start = start;
    while start > 0 && !is_separator(s[start - 1]) {
        start -= 1;
    }
    let end = token_end(s, end);
    let token = show(s, start, end);
    let raw = &s[start..end];
    let hint = if raw == b"true" || raw == b"false" {
        format!("; {ty} takes numbers, not booleans")
    } else if raw.len() > 1
        && raw
            .last()
            .is_some_and(|b| matches!(b, b'f' | b'F' | b'd' | b'D'))
        && scan_float::<f64>(&raw[..raw.len() - 1], 0).is_ok()
    {
        "; numbers take no type suffix".to_owned()
    } else if raw.starts_with(b"0x") || raw.starts_with(b"0X") {
        format!("; {ty} takes decimal numbers, not hexadecimal")
    } else {
        String::new()
    };
    SyntaxError::at((start, end), format!("`{token}` is not a number{hint}"))
}

/// The whole numbers of `s` into `values`; the offset of the first misplaced comma.
fn scan_int32s<S: Sink<i32>>(
    ty: FieldType,
    s: &[u8],
    values: &mut S,
) -> Result<Option<usize>, SyntaxError> {
    let n = s.len();
    let mut i = 0;
    let mut comma = None;
    let has_comma = memchr::memchr(b',', s).is_some();
    loop {
        i = if has_comma {
            skip_separators(ty, s, i, values.count(), &mut comma)
        } else {
            skip_whitespace(s, i)
        };
        if i >= n {
            break;
        }
        match scan_i32(s, i) {
            Ok((v, end)) => {
                values.push(v);
                // The token ends at a separator or at the end: where commas need no
                // judging, the next look can start after it.
                i = end + !has_comma as usize;
            }
            Err((error, _)) => return Err(int_error(ty, s, i, error)),
        }
    }
    Ok(comma)
}

#[cold]
fn int_error(ty: FieldType, s: &[u8], start: usize, error: IntError) -> SyntaxError {
    let end = token_end(s, start);
    let token = show(s, start, end);
    let message = match error {
        IntError::OutOfRange => {
            format!("`{token}` is out of range for {ty} (-2147483648 to 2147483647)")
        }
        IntError::Syntax if scan_float::<f64>(&s[start..end], 0).is_ok() => {
            format!("{ty} takes whole numbers, found `{token}`")
        }
        IntError::Syntax => format!("`{token}` is not a whole number"),
    };
    SyntaxError::at((start, end), message)
}

fn parse_bools(syntax: Syntax, ty: FieldType, s: &[u8]) -> Result<Scanned<bool>, SyntaxError> {
    let (yes, no, case) = match syntax {
        Syntax::Xml => ("true", "false", "X3D XML booleans are lowercase"),
        Syntax::Classic => ("TRUE", "FALSE", "ClassicVRML booleans are uppercase"),
    };
    let mut values = Vec::new();
    let mut comma = None;
    let mut after = 0;
    for (start, end) in tokens(s) {
        skip_separators(ty, &s[..start], after, values.len(), &mut comma);
        after = end;
        match &s[start..end] {
            t if t == yes.as_bytes() => values.push(true),
            t if t == no.as_bytes() => values.push(false),
            other => {
                let token = show(s, start, end);
                let message = if other.eq_ignore_ascii_case(b"true") {
                    format!("`{token}` is not a boolean: {case}: `{yes}`")
                } else if other.eq_ignore_ascii_case(b"false") {
                    format!("`{token}` is not a boolean: {case}: `{no}`")
                } else if other == b"1" {
                    format!(
                        "`{token}` is not a boolean: {ty} takes `{yes}` or `{no}`; write `{yes}`"
                    )
                } else if other == b"0" {
                    format!(
                        "`{token}` is not a boolean: {ty} takes `{yes}` or `{no}`; write `{no}`"
                    )
                } else {
                    format!("`{token}` is not a boolean: {ty} takes `{yes}` or `{no}`")
                };
                return Err(SyntaxError::at((start, end), message));
            }
        }
    }
    skip_separators(ty, s, after, values.len(), &mut comma);
    Ok((values, comma))
}

/// `"a" "b c"`: double-quoted strings separated by whitespace or commas, with `\"` and
/// `\\` as escapes (and a backslash before any other character standing for that
/// character). Text with no double quote at all (`family='SANS'`) is an error (19776-1
/// 5.15: each string is enclosed in quotation marks) that browsers read as one string.
fn parse_mfstring(text: &str) -> Result<Vec<String>, SyntaxError> {
    if !text.contains('"') {
        let s = text.as_bytes();
        let trimmed = trim_xml_whitespace(text);
        if trimmed.is_empty() {
            return Ok(Vec::new());
        }
        let start = text.len() - text.trim_start_matches([' ', '\t', '\n', '\r']).len();
        let mut error = SyntaxError::new(
            start,
            trimmed.len(),
            format!(
                "`{}` is not in quotes: each string of an MFString is enclosed in double quotes",
                show(s, start, start + trimmed.len())
            ),
        )
        .recovering(Value::Strings(vec![trimmed.to_owned()]));
        error.fix = Some(format!("\"{}\"", trimmed.replace('\\', "\\\\")));
        return Err(error);
    }
    quoted_strings(text)
}

/// ClassicVRML strings: every one quoted, an SFString exactly one.
fn parse_quoted(ty: FieldType, text: &str) -> Result<Vec<String>, SyntaxError> {
    let strings = quoted_strings(text)?;
    if !ty.is_mf() && strings.len() != 1 {
        let found = strings.len();
        return Err(SyntaxError::new(
            0,
            text.len(),
            format!("{ty} takes 1 quoted string, found {found}"),
        ));
    }
    Ok(strings)
}

/// Double-quoted strings separated by whitespace or commas (see [`parse_mfstring`]).
fn quoted_strings(text: &str) -> Result<Vec<String>, SyntaxError> {
    let s = text.as_bytes();
    let mut strings = Vec::new();
    let n = s.len();
    let mut i = 0;
    loop {
        while i < n && is_separator(s[i]) {
            i += 1;
        }
        if i >= n {
            break;
        }
        if s[i] != b'"' {
            let start = i;
            let mut end = i;
            while end < n && !is_separator(s[end]) && s[end] != b'"' {
                end += 1;
            }
            return Err(SyntaxError::at(
                (start, end),
                format!(
                    "`{}` is outside quotes: each string of an MFString is enclosed in double quotes, as in `\"a\" \"b\"`",
                    show(s, start, end)
                ),
            ));
        }
        let open = i;
        i += 1;
        let mut value = String::new();
        let mut chunk = i;
        loop {
            match memchr::memchr2(b'"', b'\\', &s[i..]) {
                None => {
                    return Err(SyntaxError::new(
                        open,
                        n - open,
                        "unterminated string: no closing `\"`",
                    ));
                }
                Some(k) => {
                    let at = i + k;
                    if s[at] == b'"' {
                        value.push_str(&text[chunk..at]);
                        i = at + 1;
                        break;
                    }
                    // A backslash: keep the character after it, whatever it is.
                    value.push_str(&text[chunk..at]);
                    if at + 1 >= n {
                        return Err(SyntaxError::new(
                            open,
                            n - open,
                            "unterminated string: no closing `\"`",
                        ));
                    }
                    chunk = at + 1;
                    // Skip the escaped character (which may be multi-byte) so that an
                    // escaped quote or backslash is taken literally.
                    let width = text[chunk..].chars().next().map_or(1, char::len_utf8);
                    i = chunk + width;
                }
            }
        }
        strings.push(value);
    }
    Ok(strings)
}

/// The images of `s`. A comma may separate the images of an MFImage, never the numbers of
/// one image (19776-1 5.1.2).
fn parse_images(ty: FieldType, s: &[u8]) -> Result<Scanned<Image>, SyntaxError> {
    let n = s.len();
    let mut images = Vec::new();
    let mut i = 0;
    let mut comma = None;
    // `allowed`: whether a comma may stand here; the first one that may not is noted.
    let skip = |i: &mut usize, allowed: bool, comma: &mut Option<usize>| {
        while *i < n && is_separator(s[*i]) {
            if s[*i] == b',' && !allowed && comma.is_none() {
                *comma = Some(*i);
            }
            *i += 1;
        }
    };
    loop {
        skip(&mut i, ty.is_mf() && !images.is_empty(), &mut comma);
        if i >= n {
            break;
        }
        let header_start = i;
        let mut header = [0i32; 3];
        for (k, slot) in header.iter_mut().enumerate() {
            if k > 0 {
                skip(&mut i, false, &mut comma);
            }
            if i >= n {
                let what = ["width", "height", "components"][k];
                let message = format!(
                    "{ty} needs `width height components` before its pixels; {what} is missing"
                );
                let mut end = n;
                while end > header_start && is_separator(s[end - 1]) {
                    end -= 1;
                }
                return Err(SyntaxError::at((header_start, end), message));
            }
            match scan_i32(s, i) {
                Ok((v, end)) => {
                    *slot = v;
                    i = end;
                }
                Err((error, _)) => return Err(image_int_error(ty, s, i, error, true)),
            }
        }
        let [width, height, components] = header;
        let mut pixels = Vec::new();
        if ty.is_mf() {
            // The size says where the next image starts; take what is there if the data
            // ends first. Never allocate from the declared size alone.
            let declared = (width.max(0) as u64).saturating_mul(height.max(0) as u64);
            pixels.reserve(declared.min(estimate(&s[i..]) as u64) as usize);
            let mut taken = 0u64;
            while taken < declared {
                skip(&mut i, false, &mut comma);
                if i >= n {
                    break;
                }
                match scan_pixel(s, i) {
                    Ok((v, end)) => {
                        pixels.push(v);
                        i = end;
                    }
                    Err((error, _)) => return Err(image_int_error(ty, s, i, error, false)),
                }
                taken += 1;
            }
        } else {
            pixels.reserve(estimate(&s[i..]));
            loop {
                skip(&mut i, false, &mut comma);
                if i >= n {
                    break;
                }
                match scan_pixel(s, i) {
                    Ok((v, end)) => {
                        pixels.push(v);
                        i = end;
                    }
                    Err((error, _)) => return Err(image_int_error(ty, s, i, error, false)),
                }
            }
        }
        trim_capacity(&mut pixels);
        images.push(Image {
            width,
            height,
            components,
            pixels,
        });
        if !ty.is_mf() {
            break;
        }
    }
    if images.is_empty() && !ty.is_mf() {
        return Err(SyntaxError::new(
            0,
            n,
            format!("{ty} takes `width height components` and then the pixels, e.g. `0 0 0`"),
        ));
    }
    Ok((images, comma))
}

#[cold]
fn image_int_error(
    ty: FieldType,
    s: &[u8],
    start: usize,
    error: IntError,
    header: bool,
) -> SyntaxError {
    let end = token_end(s, start);
    let token = show(s, start, end);
    let what = if header { "size" } else { "pixel value" };
    let message = match error {
        IntError::OutOfRange if header => {
            format!("`{token}` is out of range for an {ty} size (at most 2147483647)")
        }
        IntError::OutOfRange => {
            format!("`{token}` is out of range for an {ty} pixel value (at most 0xFFFFFFFF)")
        }
        IntError::Syntax if scan_float::<f64>(&s[start..end], 0).is_ok() => {
            format!("{ty} takes whole numbers, found `{token}` as a {what}")
        }
        IntError::Syntax => format!("`{token}` is not a whole number ({ty} {what})"),
    };
    SyntaxError::at((start, end), message)
}

#[cfg(test)]
mod tests {
    use super::*;
    use FieldType::*;

    fn ok(ty: FieldType, text: &str) -> Value {
        parse_value(ty, text).unwrap_or_else(|e| panic!("{ty} {text:?}: {e:?}"))
    }

    fn err(ty: FieldType, text: &str) -> SyntaxError {
        match parse_value(ty, text) {
            Ok(v) => panic!("{ty} {text:?} parsed as {v:?}"),
            Err(e) => e,
        }
    }

    /// The text the error points at.
    fn pointed<'a>(text: &'a str, e: &SyntaxError) -> &'a str {
        &text[e.offset..e.offset + e.len]
    }

    #[test]
    fn floats_and_separators() {
        let expected = Value::Floats(vec![1.0, 2.0, 3.0]);
        for text in ["1 2 3", " 1\t2\n3\r", "1.0 2e0 +3"] {
            assert_eq!(ok(MFVec3f, text), expected, "{text:?}");
            assert_eq!(ok(SFVec3f, text), expected, "{text:?}");
            assert_eq!(ok(SFColor, text), expected, "{text:?}");
        }
        // A comma after a whole element of an MF value (19776-1 5.1.2, EXAMPLE 1).
        assert_eq!(ok(MFVec3f, "1 2 3,"), expected);
        assert_eq!(ok(MFColor, "1 1 1, 0 0 0, ").len(), 6);
        assert_eq!(ok(MFVec3f, "1 2 3 ,, 4 5 6").len(), 6);
        assert_eq!(ok(MFFloat, "1, 2,3"), expected);
        assert_eq!(ok(MFInt32, "1,2, 3"), Value::Int32s(vec![1, 2, 3]));
        assert_eq!(ok(SFFloat, "0.5"), Value::Floats(vec![0.5]));
        assert_eq!(ok(MFFloat, ""), Value::Floats(vec![]));
        assert!(err(MFFloat, " , ")
            .message
            .contains("before the first value"));
        assert_eq!(ok(SFVec2f, "1 2"), Value::Floats(vec![1.0, 2.0]));
        assert_eq!(
            ok(SFRotation, "0 1 0 1.5"),
            Value::Floats(vec![0.0, 1.0, 0.0, 1.5])
        );
        assert_eq!(ok(MFColorRGBA, "1 0 0 1 0 1 0 0.5").len(), 8);
        assert_eq!(ok(SFMatrix3f, "1 0 0 0 1 0 0 0 1").len(), 9);
        assert_eq!(ok(SFMatrix4f, &["0"; 16].join(" ")).len(), 16);
        assert_eq!(ok(MFVec4f, "1 2 3 4 5 6 7 8").len(), 8);
        assert_eq!(ok(MFVec2f, "1 2 3 4").len(), 4);
    }

    #[test]
    fn commas_elsewhere_are_errors_read_as_whitespace() {
        let expected = Value::Floats(vec![1.0, 2.0, 3.0]);
        for (ty, text, at) in [
            (SFVec3f, "1,2,3", 1),
            (SFColor, "1, 2, 3", 1),
            (SFVec3f, "1 2 3,", 5),
            (MFVec3f, "1, 2, 3", 1),
            (MFVec3f, ",1 2 3", 0),
            (MFFloat, ", 1 2 3", 0),
        ] {
            let e = err(ty, text);
            assert_eq!((e.offset, e.len), (at, 1), "{ty} {text:?}");
            assert_eq!(e.into_recovered(), Some(expected.clone()), "{ty} {text:?}");
        }
        // EXAMPLE 2 of 19776-1 5.1.2.
        let e = err(MFColor, "1, 1, 1, 0, 0, 0");
        assert_eq!(
            e.message,
            "a comma inside an SFColor of an MFColor: commas may only separate whole SFColor values (after every 3 numbers), as in `1 2 3, 4 5 6`"
        );
        assert_eq!(e.fix.as_deref(), Some("1 1 1, 0 0 0"));
        let e = err(SFColor, "1,0,0");
        assert_eq!(
            e.message,
            "a comma inside an SFColor: commas may only separate the values of an MF field"
        );
        assert_eq!(e.fix.as_deref(), Some("1 0 0"));
        // Commas after every 3 numbers of an MFVec2d: x y w triples, not pairs to regroup.
        let e = err(MFVec2d, "0 -27.12 1,6.28 -27.12 1,");
        assert_eq!(e.fix, None);
        assert_eq!(
            e.message,
            "commas after every 3 numbers, but each SFVec2d of an MFVec2d has 2: commas may only separate whole SFVec2d values"
        );
        assert_eq!(
            e.help.as_deref(),
            Some("3 numbers between commas: is this an MFVec3d's value?")
        );
        // The count is judged first: one error per value.
        let e = err(MFColor, "1 1 1, 0 0");
        assert!(e.message.contains("multiple of 3"), "{}", e.message);
        assert_eq!(
            err(SFInt32, "1,").into_recovered(),
            Some(Value::Int32s(vec![1]))
        );
        assert_eq!(
            err(SFBool, "true,").into_recovered(),
            Some(Value::Bools(vec![true]))
        );
        assert_eq!(ok(MFBool, "true, false"), Value::Bools(vec![true, false]));
        assert_eq!(err(SFImage, "1 1 1, 0xFF").offset, 5);
        assert_eq!(err(MFImage, "1 1, 1 0xFF").offset, 3);
        assert_eq!(ok(MFImage, "1 1 1 0xFF, 0 0 0,").len(), 2);
    }

    #[test]
    fn doubles() {
        assert_eq!(ok(SFTime, "-1"), Value::Doubles(vec![-1.0]));
        assert_eq!(ok(SFDouble, "0.1"), Value::Doubles(vec![0.1]));
        assert_eq!(ok(MFTime, "0 1.5"), Value::Doubles(vec![0.0, 1.5]));
        assert_eq!(
            ok(SFVec3d, "1e300 2 3"),
            Value::Doubles(vec![1e300, 2.0, 3.0])
        );
        assert_eq!(ok(MFVec2d, "1 2 3 4").len(), 4);
        assert_eq!(ok(MFVec4d, "").len(), 0);
        assert_eq!(ok(SFMatrix3d, &["1"; 9].join(" ")).len(), 9);
        assert_eq!(ok(MFMatrix4d, &["1"; 32].join(" ")).len(), 32);
        assert_eq!(ok(MFDouble, "1").len(), 1);
        let e = err(SFVec3d, "1 2");
        assert_eq!(e.message, "SFVec3d takes 3 numbers, found 2");
    }

    #[test]
    fn non_finite_values_are_kept() {
        let Value::Floats(v) = ok(MFFloat, "NaN INF -INF inf -Infinity 1e39") else {
            panic!()
        };
        assert!(v[0].is_nan());
        assert_eq!(
            &v[1..],
            &[
                f32::INFINITY,
                f32::NEG_INFINITY,
                f32::INFINITY,
                f32::NEG_INFINITY,
                f32::INFINITY
            ]
        );
        let Value::Floats(v) = ok(SFFloat, "-0") else {
            panic!()
        };
        assert_eq!(v[0].to_bits(), (-0.0f32).to_bits());
    }

    #[test]
    fn float_errors() {
        let text = "1 2 abc 4";
        let e = err(MFFloat, text);
        assert_eq!((e.offset, e.len), (4, 3));
        assert_eq!(e.message, "`abc` is not a number");
        let text = "0 1.2.3";
        let e = err(MFFloat, text);
        assert_eq!(pointed(text, &e), "1.2.3");
        let text = "1 true";
        let e = err(MFFloat, text);
        assert_eq!(pointed(text, &e), "true");
        assert!(e.message.contains("not booleans"), "{}", e.message);
        let e = err(SFFloat, "1.5f");
        assert!(e.message.contains("suffix"), "{}", e.message);
        let e = err(SFFloat, "0xFF");
        assert!(e.message.contains("hexadecimal"), "{}", e.message);
        let text = "1 2 é";
        let e = err(MFFloat, text);
        assert_eq!(pointed(text, &e), "é");
        let text = "1 2;3";
        let e = err(MFFloat, text);
        assert_eq!(pointed(text, &e), "2;3");
        let long = format!("1 {}", "x".repeat(1000));
        let e = err(MFFloat, &long);
        assert_eq!((e.offset, e.len), (2, 1000));
        assert!(e.message.len() < 100);
    }

    #[test]
    fn arity_errors() {
        let text = "1 0";
        let e = err(SFColor, text);
        assert_eq!(e.message, "SFColor takes 3 numbers, found 2");
        assert_eq!(pointed(text, &e), "1 0");
        let text = "1 2 3 4 5 6 7";
        let e = err(MFVec3f, text);
        assert_eq!(e.message, "MFVec3f takes a multiple of 3 numbers, found 7");
        assert_eq!(pointed(text, &e), "7");
        let text = "1 2 3, 4 5,";
        let e = err(MFVec3f, text);
        assert_eq!(pointed(text, &e), "4 5");
        let text = "1 2";
        let e = err(SFFloat, text);
        assert_eq!(e.message, "SFFloat takes 1 number, found 2");
        assert_eq!(pointed(text, &e), "2");
        let text = "1 2 3 4 5";
        let e = err(SFVec3f, text);
        assert_eq!(pointed(text, &e), "4 5");
        let e = err(SFFloat, "");
        assert_eq!(e.message, "SFFloat takes 1 number, found none");
        assert_eq!((e.offset, e.len), (0, 0));
        let e = err(SFVec3f, "  ");
        assert_eq!((e.offset, e.len), (0, 2));
        let e = err(SFInt32, "1 2");
        assert_eq!(e.message, "SFInt32 takes 1 number, found 2");
        let e = err(SFBool, "true false");
        assert_eq!(e.message, "SFBool takes 1 value, found 2");
        let e = err(SFBool, "");
        assert_eq!(e.message, "SFBool takes 1 value, found none");
        let e = err(SFRotation, "0 1 0");
        assert_eq!(e.message, "SFRotation takes 4 numbers, found 3");
        let e = err(MFColorRGBA, "1 1 1");
        assert_eq!(
            e.message,
            "MFColorRGBA takes a multiple of 4 numbers, found 3"
        );
    }

    #[test]
    fn bools() {
        assert_eq!(ok(SFBool, "true"), Value::Bools(vec![true]));
        assert_eq!(ok(SFBool, " false "), Value::Bools(vec![false]));
        assert_eq!(
            ok(MFBool, "true, false true"),
            Value::Bools(vec![true, false, true])
        );
        assert_eq!(ok(MFBool, ""), Value::Bools(vec![]));
        let e = err(SFBool, "True");
        assert!(
            e.message.contains("X3D XML booleans are lowercase: `true`"),
            "{}",
            e.message
        );
        assert_eq!((e.offset, e.len), (0, 4));
        let e = err(MFBool, "true FALSE");
        assert!(e.message.contains("lowercase: `false`"), "{}", e.message);
        assert_eq!((e.offset, e.len), (5, 5));
        let e = err(SFBool, "TRUE");
        assert!(e.message.contains("lowercase"));
        let e = err(SFBool, "1");
        assert!(e.message.contains("write `true`"), "{}", e.message);
        let e = err(SFBool, "yes");
        assert!(e.message.contains("`true` or `false`"), "{}", e.message);
    }

    #[test]
    fn int32s() {
        assert_eq!(ok(SFInt32, "-5"), Value::Int32s(vec![-5]));
        assert_eq!(ok(SFInt32, "0xFF"), Value::Int32s(vec![255]));
        assert_eq!(
            ok(MFInt32, "0 1 2 -1, 3 0X10"),
            Value::Int32s(vec![0, 1, 2, -1, 3, 16])
        );
        assert_eq!(ok(MFInt32, ""), Value::Int32s(vec![]));
        assert_eq!(
            ok(MFInt32, "2147483647 -2147483648"),
            Value::Int32s(vec![i32::MAX, i32::MIN])
        );
        let text = "1 1.5 2";
        let e = err(SFInt32, text);
        assert_eq!(e.message, "SFInt32 takes whole numbers, found `1.5`");
        assert_eq!(pointed(text, &e), "1.5");
        let e = err(MFInt32, text);
        assert_eq!(e.message, "MFInt32 takes whole numbers, found `1.5`");
        let text = "0 2147483648";
        let e = err(MFInt32, text);
        assert!(e.message.contains("out of range"), "{}", e.message);
        assert_eq!(pointed(text, &e), "2147483648");
        let e = err(MFInt32, "1 x");
        assert_eq!(e.message, "`x` is not a whole number");
        assert_eq!((e.offset, e.len), (2, 1));
        let e = err(SFInt32, "");
        assert_eq!(e.message, "SFInt32 takes 1 number, found none");
    }

    #[test]
    fn strings() {
        assert_eq!(
            ok(SFString, " a \"b\" "),
            Value::Strings(vec![" a \"b\" ".into()])
        );
        assert_eq!(ok(SFString, ""), Value::Strings(vec![String::new()]));
        assert_eq!(
            ok(MFString, r#""a" "b c""#),
            Value::Strings(vec!["a".into(), "b c".into()])
        );
        assert_eq!(
            ok(MFString, r#" "a","b" , "" "#),
            Value::Strings(vec!["a".into(), "b".into(), "".into()])
        );
        assert_eq!(
            ok(MFString, r#""a""b""#),
            Value::Strings(vec!["a".into(), "b".into()])
        );
        assert_eq!(ok(MFString, ""), Value::Strings(vec![]));
        assert_eq!(ok(MFString, "  \n"), Value::Strings(vec![]));
        assert_eq!(
            ok(MFString, r#""He said, \"Immel did it!\"""#),
            Value::Strings(vec![r#"He said, "Immel did it!""#.into()])
        );
        assert_eq!(
            ok(MFString, r#""a\\b""#),
            Value::Strings(vec![r"a\b".into()])
        );
        assert_eq!(ok(MFString, r#""a\\""#), Value::Strings(vec![r"a\".into()]));
        assert_eq!(
            ok(MFString, r#""a\nb""#),
            Value::Strings(vec!["anb".into()])
        );
        assert_eq!(
            ok(MFString, r#""\é" "ü""#),
            Value::Strings(vec!["é".into(), "ü".into()])
        );
        assert_eq!(
            ok(MFString, "\"line\none\""),
            Value::Strings(vec!["line\none".into()])
        );
    }

    #[test]
    fn unquoted_mfstring_is_an_error_read_as_one_string() {
        let e = err(MFString, "texture.png");
        assert_eq!(
            e.message,
            "`texture.png` is not in quotes: each string of an MFString is enclosed in double quotes"
        );
        assert_eq!(e.fix.as_deref(), Some("\"texture.png\""));
        assert_eq!(
            e.into_recovered(),
            Some(Value::Strings(vec!["texture.png".into()]))
        );
        let text = "  Hello world \n";
        let e = err(MFString, text);
        assert_eq!(pointed(text, &e), "Hello world");
        assert_eq!(e.fix.as_deref(), Some("\"Hello world\""));
        assert_eq!(
            err(MFString, r"C:\a.png").fix.as_deref(),
            Some(r#""C:\\a.png""#)
        );
        assert_eq!(ok(MFString, "  "), Value::Strings(vec![]));
    }

    #[test]
    fn mfstring_errors() {
        let text = r#""a" "b"#;
        let e = err(MFString, text);
        assert_eq!(pointed(text, &e), "\"b");
        assert!(e.message.contains("unterminated"));
        let text = r#""a\""#;
        let e = err(MFString, text);
        assert_eq!((e.offset, e.len), (0, 4));
        let text = r#""a\"#;
        let e = err(MFString, text);
        assert!(e.message.contains("unterminated"));
        let text = r#""a" b "c""#;
        let e = err(MFString, text);
        assert_eq!(pointed(text, &e), "b");
        assert!(e.message.contains("outside quotes"), "{}", e.message);
        let text = r#"Hello "World""#;
        let e = err(MFString, text);
        assert_eq!(pointed(text, &e), "Hello");
        let text = r#""a"b"#;
        let e = err(MFString, text);
        assert_eq!(pointed(text, &e), "b");
    }

    #[test]
    fn sfimage() {
        assert_eq!(
            ok(SFImage, "0 0 0"),
            Value::Images(vec![Image {
                width: 0,
                height: 0,
                components: 0,
                pixels: vec![]
            }])
        );
        assert_eq!(
            ok(SFImage, "2 1 3 0xFF0000 0x00FF00"),
            Value::Images(vec![Image {
                width: 2,
                height: 1,
                components: 3,
                pixels: vec![0xFF0000, 0x00FF00]
            }])
        );
        // Pixel count is not checked here; negative values are their bit patterns.
        assert_eq!(
            ok(SFImage, "1 1 4 -1 4294967295 0xFFFFFFFF"),
            Value::Images(vec![Image {
                width: 1,
                height: 1,
                components: 4,
                pixels: vec![u32::MAX; 3]
            }])
        );
        assert_eq!(
            ok(SFImage, "2 2 1"),
            Value::Images(vec![Image {
                width: 2,
                height: 2,
                components: 1,
                pixels: vec![]
            }])
        );
        let e = err(SFImage, "");
        assert!(
            e.message.contains("width height components"),
            "{}",
            e.message
        );
        let e = err(SFImage, "  ");
        assert!(
            e.message.contains("width height components"),
            "{}",
            e.message
        );
        let text = "1 1";
        let e = err(SFImage, text);
        assert!(e.message.contains("components is missing"), "{}", e.message);
        assert_eq!(pointed(text, &e), "1 1");
        let text = "1 1 1 0.5";
        let e = err(SFImage, text);
        assert_eq!(pointed(text, &e), "0.5");
        assert!(e.message.contains("whole numbers"));
        let text = "1 1 1 4294967296";
        let e = err(SFImage, text);
        assert_eq!(pointed(text, &e), "4294967296");
        let text = "1 x 1";
        let e = err(SFImage, text);
        assert_eq!(pointed(text, &e), "x");
        let text = "4294967295 1 1";
        let e = err(SFImage, text);
        assert!(e.message.contains("size"), "{}", e.message);
    }

    #[test]
    fn mfimage() {
        assert_eq!(ok(MFImage, ""), Value::Images(vec![]));
        let Value::Images(images) = ok(MFImage, "1 2 1 0xFF 0x80, 2 1 3 1 2 0 0 0") else {
            panic!()
        };
        assert_eq!(images.len(), 3);
        assert_eq!(
            images[0],
            Image {
                width: 1,
                height: 2,
                components: 1,
                pixels: vec![255, 128]
            }
        );
        assert_eq!(
            images[1],
            Image {
                width: 2,
                height: 1,
                components: 3,
                pixels: vec![1, 2]
            }
        );
        assert_eq!(
            images[2],
            Image {
                width: 0,
                height: 0,
                components: 0,
                pixels: vec![]
            }
        );
        // Short last image: takes what is there.
        let Value::Images(images) = ok(MFImage, "2 2 1 1 2 3") else {
            panic!()
        };
        assert_eq!(
            images,
            vec![Image {
                width: 2,
                height: 2,
                components: 1,
                pixels: vec![1, 2, 3]
            }]
        );
        // A huge declared size allocates nothing of its own.
        let Value::Images(images) = ok(MFImage, "2147483647 2147483647 4 1 2") else {
            panic!()
        };
        assert_eq!(images[0].pixels, vec![1, 2]);
        // Negative sizes hold no pixels: the next numbers start the next image.
        let Value::Images(images) = ok(MFImage, "-1 5 1 0 0 0") else {
            panic!()
        };
        assert_eq!(images.len(), 2);
        let text = "1 1 1 5 2 2";
        let e = err(MFImage, text);
        assert!(e.message.contains("components is missing"), "{}", e.message);
        assert_eq!(pointed(text, &e), "2 2");
    }

    #[test]
    fn nodes_are_not_attribute_text() {
        let e = err(SFNode, "NULL");
        assert_eq!((e.offset, e.len), (0, 4));
        assert!(e.message.contains("child elements"));
        let e = err(MFNode, "");
        assert!(e.message.contains("MFNode"));
    }

    #[test]
    fn every_type_handles_odd_input_without_panicking() {
        let inputs = [
            "",
            " ",
            ",",
            "\"",
            "\\",
            "é",
            "1é",
            "0x",
            "-",
            ".",
            "e",
            "1e",
            "\"\\",
            "\"a\\\"",
            "1 2 3 4 5 6 7 8 9 10 11 12 13 14 15 16 17",
        ];
        let digits = "9".repeat(10_000);
        for &ty in FieldType::ALL {
            for text in inputs.iter().copied().chain([digits.as_str()]) {
                let _ = parse_value(ty, text);
            }
        }
    }

    #[test]
    fn error_ranges_are_char_boundaries() {
        for &ty in FieldType::ALL {
            for text in ["ü 1", "1 ü", "\"ü\" ü", "ü", "1 2 ü€"] {
                if let Err(e) = parse_value(ty, text) {
                    assert!(
                        text.get(e.offset..e.offset + e.len).is_some(),
                        "{ty} {text:?} {e:?}"
                    );
                }
            }
        }
    }

    /// Times parsing 10 million floats; run with
    /// `cargo test --release --lib xml_value::tests::throughput -- --ignored --nocapture`.
    #[test]
    #[ignore]
    fn throughput() {
        let count = 10_000_000;
        let mut text = String::with_capacity(count * 9);
        for k in 0..count {
            text.push_str(if k % 2 == 0 { "-12.3456 " } else { "7.891011 " });
        }
        for _ in 0..3 {
            let start = std::time::Instant::now();
            let value = parse_value(MFVec3f, &text[..text.len() - 9 * (count % 3)]).unwrap();
            let elapsed = start.elapsed();
            assert_eq!(value.len(), count - count % 3);
            eprintln!(
                "MFVec3f: {:.2} ns/number",
                elapsed.as_nanos() as f64 / value.len() as f64
            );
        }
    }
}
