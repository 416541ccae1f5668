//! Field values in the JSON encoding (ISO/IEC 19776-5): a JSON value of the scanned
//! [`Tree`] turned into a typed [`Value`] for the field's type.
//!
//! SFBool is `true`/`false`; SFInt32, SFFloat, SFDouble and SFTime are numbers; vectors,
//! colours, rotations and matrices are arrays of numbers, MF types one flat array
//! (`[0,0,0, 1,0,0]`) whose length is a multiple of the arity; SFString is a string and
//! MFString an array of strings (a lone string is taken as a list of one, as some
//! exporters write it); SFImage is `[width, height, components, pixel…]` and MFImage
//! those concatenated. Numbers are read from their text straight into the field's
//! precision (an SFFloat `1e39` is +∞ for a rule to report, not an error here), into one
//! vector per field.

use std::ops::Range;

use rayon::prelude::*;

use super::tree::{tight_number, Kind, ScanNumber, Tree, ValueRef, NOT_INTEGER};
use crate::model::text::number::{is_separator, parse_f32, parse_f64, scan_float, scan_i32};
use crate::model::text::{huge_vec, split};
use crate::model::{Image, Node, Sink, Summarized, Summarizer, Value};
use crate::schema::{FieldDef, FieldType, Scalar};

/// A value that does not fit its field's type. `span` is a byte range in the input: the
/// offending element, or the whole value.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct ValueError {
    pub span: (usize, usize),
    /// The MF element at fault, where one is.
    pub index: Option<usize>,
    pub message: String,
    pub help: Option<String>,
}

impl ValueError {
    fn new(span: (usize, usize), message: impl Into<String>) -> ValueError {
        ValueError {
            span,
            index: None,
            message: message.into(),
            help: None,
        }
    }

    fn index(mut self, index: usize) -> ValueError {
        self.index = Some(index);
        self
    }

    fn help(mut self, help: impl Into<String>) -> ValueError {
        self.help = Some(help.into());
        self
    }
}

/// [`convert`] for the schema field `def` of `node`, a numeric MF field
/// ([`Summary::applies_to`](crate::model::Summary::applies_to)), keeping a
/// [`Summary`](crate::model::Summary) instead of its numbers (the fast
/// level): the same numbers are read, the same errors reported, and the summary says what
/// the fast-level rules would find.
pub fn convert_summary(
    tree: &Tree,
    i: usize,
    node: &Node,
    def: &'static FieldDef,
) -> Result<Value, ValueError> {
    match def.ty.scalar() {
        Scalar::Float => summarize(tree, i, node, def, &FLOAT32),
        Scalar::Double => summarize(tree, i, node, def, &FLOAT64),
        _ => summarize(tree, i, node, def, &INT32),
    }
}

fn summarize<T: Summarized + Send + 'static>(
    tree: &Tree,
    i: usize,
    node: &Node,
    def: &'static FieldDef,
    number: &NumberType<T>,
) -> Result<Value, ValueError> {
    let mut summarizer = Summarizer::new(node, def);
    numbers_into(tree, i, def.ty, number, &mut summarizer)?;
    Ok(summarizer.finish())
}

/// Converts the JSON value at item `i` to a value of type `ty`. Node types are not values
/// (their nodes are `-name` members); asking for one is an error.
pub fn convert(tree: &Tree, i: usize, ty: FieldType) -> Result<Value, ValueError> {
    match ty.scalar() {
        Scalar::Bool => bools(tree, i, ty).map(Value::Bools),
        Scalar::Int32 => numbers(tree, i, ty, &INT32).map(Value::Int32s),
        Scalar::Float => numbers(tree, i, ty, &FLOAT32).map(Value::Floats),
        Scalar::Double => numbers(tree, i, ty, &FLOAT64).map(Value::Doubles),
        Scalar::String => strings(tree, i, ty).map(Value::Strings),
        Scalar::Image => images(tree, i, ty).map(Value::Images),
        Scalar::Node => Err(ValueError::new(
            tree.full_span(i),
            format!("{ty} fields take nodes, not a value"),
        )),
    }
}

/// What a JSON value is, for messages: `a string ("1")`, `an array`, `null`.
pub fn describe(tree: &Tree, v: impl Into<ValueRef>) -> String {
    let i = v.into();
    match tree.kind(i) {
        Kind::Null => "null".to_string(),
        Kind::True => "`true`".to_string(),
        Kind::False => "`false`".to_string(),
        Kind::Number => format!("the number {}", short(tree.raw(i))),
        Kind::String | Kind::Key => format!("the string \"{}\"", short(tree.raw(i))),
        Kind::Array if tree.item(i).len == 0 => "an empty array".to_string(),
        Kind::Array => "an array".to_string(),
        Kind::Object => "an object".to_string(),
    }
}

fn short(text: &str) -> String {
    const MAX: usize = 40;
    match text.char_indices().nth(MAX) {
        Some((cut, _)) => format!("{}…", &text[..cut]),
        None => text.to_string(),
    }
}

/// What one element of the type is, for messages.
fn element_noun(ty: FieldType) -> (&'static str, &'static str) {
    match ty.scalar() {
        Scalar::Bool => ("boolean", "booleans"),
        Scalar::Int32 => ("whole number", "whole numbers"),
        Scalar::String => ("string", "strings"),
        _ => ("number", "numbers"),
    }
}

fn plural(n: usize, (one, many): (&str, &str)) -> String {
    if n == 1 {
        format!("1 {one}")
    } else {
        format!("{n} {many}")
    }
}

/// What the whole value should look like.
fn expected(ty: FieldType) -> String {
    let noun = element_noun(ty);
    let article = if noun.0.starts_with(['a', 'e', 'i', 'o', 'u']) {
        "an"
    } else {
        "a"
    };
    if ty == FieldType::SFImage {
        "an array [width, height, components, pixel…]".to_string()
    } else if ty == FieldType::MFImage {
        "an array of images, each width, height, components, pixel…".to_string()
    } else if ty.is_mf() && ty.arity() > 1 {
        format!("an array of {}, a multiple of {}", noun.1, ty.arity())
    } else if ty.is_mf() {
        format!("an array of {}", noun.1)
    } else if ty.arity() > 1 {
        format!("an array of {}", plural(ty.arity(), noun))
    } else {
        format!("{article} {}", noun.0)
    }
}

/// The error for a value of the wrong JSON kind, with a hint for the usual slips.
#[cold]
fn wrong_kind(tree: &Tree, i: usize, ty: FieldType) -> ValueError {
    let error = ValueError::new(
        tree.full_span(i),
        format!("{ty} takes {}, found {}", expected(ty), describe(tree, i)),
    );
    match (tree.kind(i), ty.scalar()) {
        (Kind::String, Scalar::Int32 | Scalar::Float | Scalar::Double)
            if looks_numeric(tree.raw(i)) =>
        {
            error.help("JSON numbers are written without quotes")
        }
        (Kind::String, Scalar::Bool)
            if matches!(tree.raw(i), "true" | "false" | "TRUE" | "FALSE") =>
        {
            error.help("JSON booleans are written `true` or `false`, without quotes")
        }
        (Kind::Number, Scalar::Bool) if matches!(tree.raw(i), "0" | "1") => {
            error.help("write `true` or `false`")
        }
        (Kind::Array, _) if !ty.is_mf() && ty.arity() == 1 && tree.item(i).len == 1 => {
            error.help(format!("{ty} is a single value: drop the brackets"))
        }
        (Kind::Number | Kind::True | Kind::False, _) if ty.is_mf() || ty.arity() > 1 => {
            error.help("put the value in an array: `[…]`")
        }
        _ => error,
    }
}

fn looks_numeric(text: &str) -> bool {
    let mut any = false;
    for token in text
        .split([' ', ',', '\t', '\n', '\r'])
        .filter(|t| !t.is_empty())
    {
        if parse_f64(token.as_bytes()).is_none() {
            return false;
        }
        any = true;
    }
    any
}

/// The count check: exactly the arity for SF types, a multiple of it for MF types.
fn check_count(tree: &Tree, array: usize, ty: FieldType, count: usize) -> Result<(), ValueError> {
    let arity = ty.arity();
    let noun = element_noun(ty);
    if ty.is_mf() {
        if count.is_multiple_of(arity) {
            return Ok(());
        }
        // Point at the incomplete last element.
        let first = count - count % arity;
        return Err(ValueError::new(
            elements_span(tree, array, first),
            format!("{ty} takes a multiple of {arity} {}, found {count}", noun.1),
        )
        .index(first / arity));
    }
    if count == arity {
        return Ok(());
    }
    let found = if count == 0 {
        "none".to_string()
    } else {
        count.to_string()
    };
    let span = if count > arity {
        // Point at the surplus.
        elements_span(tree, array, arity)
    } else {
        tree.full_span(array)
    };
    Err(ValueError::new(
        span,
        format!("{ty} takes {}, found {found}", plural(arity, noun)),
    ))
}

/// The span from element `first` of `array` to its last element (the whole array when
/// there are none from there).
fn elements_span(tree: &Tree, array: usize, first: usize) -> (usize, usize) {
    let mut rest = tree.elements(array).skip(first);
    match rest.next() {
        Some(a) => {
            let last = rest.last().unwrap_or(a);
            (tree.full_span(a).0, tree.full_span(last).1)
        }
        None => tree.full_span(array),
    }
}

fn bools(tree: &Tree, i: usize, ty: FieldType) -> Result<Vec<bool>, ValueError> {
    let one = |e: ValueRef| match tree.kind(e) {
        Kind::True => Some(true),
        Kind::False => Some(false),
        _ => None,
    };
    if !ty.is_mf() {
        return one(i.into())
            .map(|b| vec![b])
            .ok_or_else(|| wrong_kind(tree, i, ty));
    }
    if tree.kind(i) != Kind::Array {
        return Err(wrong_kind(tree, i, ty));
    }
    let mut values = Vec::with_capacity(tree.item(i).len as usize);
    for (index, e) in tree.elements(i).enumerate() {
        match one(e) {
            Some(b) => values.push(b),
            None => return Err(element_error(tree, e, ty, index)),
        }
    }
    Ok(values)
}

/// An MF element (or a vector's component) of the wrong kind.
#[cold]
fn element_error(tree: &Tree, e: ValueRef, ty: FieldType, index: usize) -> ValueError {
    let noun = element_noun(ty);
    let error = ValueError::new(
        tree.full_span(e),
        format!("{ty} takes {}, found {}", noun.1, describe(tree, e)),
    );
    let error = if ty.is_mf() {
        error.index(index / ty.arity())
    } else {
        error
    };
    match tree.kind(e) {
        Kind::String
            if matches!(ty.scalar(), Scalar::Int32 | Scalar::Float | Scalar::Double)
                && looks_numeric(tree.raw(e)) =>
        {
            error.help("JSON numbers are written without quotes")
        }
        Kind::Array if ty.arity() > 1 => error.help(format!(
            "{ty} is one flat array of numbers ([0,0,0, 1,0,0]), not an array of arrays"
        )),
        _ => error,
    }
}

/// Reads one number from its text and whether it is written as an integer;
/// `Err(message)` when it does not fit.
type Scalarize<T> = fn(&[u8], bool) -> Result<T, String>;

fn int32(text: &[u8], integer_syntax: bool) -> Result<i32, String> {
    let out_of_range = || {
        Err(format!(
            "{} is out of range (-2147483648 to 2147483647)",
            String::from_utf8_lossy(text)
        ))
    };
    if integer_syntax {
        // JSON integer syntax: `-?` and digits. Ten digits fit an i64 with room to spare.
        let (negative, digits) = match text.split_first() {
            Some((b'-', rest)) => (true, rest),
            _ => (false, text),
        };
        if digits.len() > 10 {
            return out_of_range();
        }
        let magnitude = digits
            .iter()
            .fold(0i64, |m, &d| m * 10 + i64::from(d.wrapping_sub(b'0')));
        let v = if negative { -magnitude } else { magnitude };
        return i32::try_from(v).or_else(|_| out_of_range());
    }
    match whole_number(text) {
        Some(v) => i32::try_from(v).or_else(|_| out_of_range()),
        None => Err(format!(
            "whole numbers only, found {}",
            String::from_utf8_lossy(text)
        )),
    }
}

/// The value of a JSON number's text when it is a whole number, saturated at ±i64::MAX;
/// None when it has a non-zero fractional part. Decided on the decimal digits themselves:
/// through f64, `1.00000000000000000001` and `1e-400` would round to whole numbers.
fn whole_number(text: &[u8]) -> Option<i64> {
    let (negative, rest) = match text.split_first() {
        Some((b'-', rest)) => (true, rest),
        _ => (false, text),
    };
    let (mantissa, exponent) = match rest.iter().position(|&b| b | 0x20 == b'e') {
        Some(at) => (&rest[..at], &rest[at + 1..]),
        None => (rest, &[][..]),
    };
    let (int, fraction) = match mantissa.iter().position(|&b| b == b'.') {
        Some(at) => (&mantissa[..at], &mantissa[at + 1..]),
        None => (mantissa, &[][..]),
    };
    let (exponent_negative, exponent) = match exponent.split_first() {
        Some((b'-', rest)) => (true, rest),
        Some((b'+', rest)) => (false, rest),
        _ => (false, exponent),
    };
    // Saturated far beyond any digit count an input can hold.
    let exponent = exponent.iter().fold(0i64, |e, &d| {
        (e * 10 + i64::from(d.wrapping_sub(b'0'))).min(1 << 40)
    });
    // Digits before `point` (counted from the first digit) are the integer part.
    let point = int.len() as i64
        + if exponent_negative {
            -exponent
        } else {
            exponent
        };
    let mut magnitude: i64 = 0;
    let mut k: i64 = 0;
    for &d in int.iter().chain(fraction) {
        let d = i64::from(d.wrapping_sub(b'0'));
        if k < point {
            magnitude = magnitude.saturating_mul(10).saturating_add(d);
        } else if d != 0 {
            return None;
        }
        k += 1;
    }
    // The zeros the exponent adds after the last digit (a few suffice to saturate).
    while k < point && magnitude != 0 && magnitude != i64::MAX {
        magnitude = magnitude.saturating_mul(10);
        k += 1;
    }
    Some(if negative { -magnitude } else { magnitude })
}

fn float32(text: &[u8], _: bool) -> Result<f32, String> {
    // The scanner checked the JSON number syntax, which the number parser accepts.
    Ok(parse_f32(text).unwrap_or(f32::NAN))
}

fn float64(text: &[u8], _: bool) -> Result<f64, String> {
    Ok(parse_f64(text).unwrap_or(f64::NAN))
}

/// How the numbers of one scalar type are read.
struct NumberType<T> {
    /// In one pass over an array's text ([`Elements::next_number`]): nearly every number.
    ///
    /// [`Elements::next_number`]: super::tree::Elements::next_number
    scan: ScanNumber<T>,
    /// Single values, and what `scan` refuses.
    read: Scalarize<T>,
}

/// `scan_i32` takes JSON integers, and refuses the rest for [`int32`].
const INT32: NumberType<i32> = NumberType {
    scan: |text, at| scan_i32(text, at).ok(),
    read: int32,
};

/// `scan_float` takes every JSON number, correctly rounded straight to the type.
const FLOAT32: NumberType<f32> = NumberType {
    scan: |text, at| scan_float(text, at).ok(),
    read: float32,
};

const FLOAT64: NumberType<f64> = NumberType {
    scan: |text, at| scan_float(text, at).ok(),
    read: float64,
};

/// A number element or value read by `read`; `None` when it is not a number.
#[inline(always)]
fn scalar<T>(tree: &Tree, e: ValueRef, read: Scalarize<T>) -> Option<Result<T, String>> {
    let item = tree.item(e);
    (item.kind == Kind::Number).then(|| read(tree.raw_bytes(e), item.flags & NOT_INTEGER == 0))
}

fn numbers<T: Copy + Send + 'static>(
    tree: &Tree,
    i: usize,
    ty: FieldType,
    number: &NumberType<T>,
) -> Result<Vec<T>, ValueError> {
    if !ty.is_mf() && ty.arity() == 1 {
        return match scalar(tree, i.into(), number.read) {
            Some(Ok(v)) => Ok(vec![v]),
            Some(Err(message)) => Err(bad_number(tree, ty, i.into(), message, None)),
            None => Err(wrong_kind(tree, i, ty)),
        };
    }
    let capacity = if tree.kind(i) == Kind::Array {
        tree.item(i).len as usize
    } else {
        0
    };
    let mut values = huge_vec::with_capacity(capacity);
    numbers_into(tree, i, ty, number, &mut values)?;
    Ok(values)
}

/// A number of a `ty` value that did not read: at element `index / arity` of an MF value.
fn bad_number(
    tree: &Tree,
    ty: FieldType,
    e: ValueRef,
    message: String,
    index: Option<usize>,
) -> ValueError {
    let error = ValueError::new(
        tree.full_span(e),
        format!("{ty} takes {}: {message}", element_noun(ty).1),
    );
    match index {
        Some(index) if ty.is_mf() => error.index(index / ty.arity()),
        _ => error,
    }
}

/// The numbers of the array at item `i` into `values`, its count checked.
fn numbers_into<T: Copy + Send + 'static, S: Sink<T>>(
    tree: &Tree,
    i: usize,
    ty: FieldType,
    number: &NumberType<T>,
    values: &mut S,
) -> Result<(), ValueError> {
    if tree.kind(i) != Kind::Array {
        return Err(wrong_kind(tree, i, ty));
    }
    if let Some(pieces) = numbers_in_pieces(tree, i, number.scan) {
        for numbers in pieces {
            values.extend_from(&numbers);
            split::scratch::give_back(numbers);
        }
        return check_count(tree, i, ty, values.count());
    }
    let mut elements = tree.elements(i);
    loop {
        if let Some(v) = elements.next_number(number.scan) {
            values.push(v);
            continue;
        }
        // Not a number, or one `scan` refuses: read it on its own, or report it.
        let Some(e) = elements.next() else { break };
        let index = values.count();
        match scalar(tree, e, number.read) {
            Some(Ok(v)) => values.push(v),
            Some(Err(message)) => return Err(bad_number(tree, ty, e, message, Some(index))),
            None => return Err(element_error(tree, e, ty, index)),
        }
    }
    check_count(tree, i, ty, values.count())
}

/// The numbers of a long array holding numbers only, read in pieces on the pool's
/// threads ([`split`]), each piece's in a vector. `None` when the array is short, or holds
/// anything [`Elements::next_number`] leaves to the one-by-one reading (which then reads
/// the array and reports what is wrong), so the numbers are always those it would read.
///
/// [`Elements::next_number`]: super::tree::Elements::next_number
fn numbers_in_pieces<T: Copy + Send + 'static>(
    tree: &Tree,
    array: usize,
    scan: ScanNumber<T>,
) -> Option<Vec<Vec<T>>> {
    let text = tree.array_text(array);
    let piece = split::piece_size(text.len(), rayon::current_num_threads)?;
    let tight = tree.is_unchecked(array);
    let pieces = split::pieces(text, piece)
        .into_par_iter()
        .map(|range| {
            if tight {
                numbers_of_tight_piece(text, range, scan)
            } else {
                numbers_of_piece(text, range, scan)
            }
        })
        .collect::<Option<Vec<_>>>()?;
    let count: usize = pieces.iter().map(Vec::len).sum();
    let whole = count == tree.item(array).len as usize;
    if whole && tight {
        tree.mark_checked(array);
    }
    whole.then_some(pieces)
}

/// [`numbers_of_piece`] for an array the scanner skipped ([`Tree::is_unchecked`]): each
/// number with its comma checked by [`tight_number`]. A piece but the first starts at the
/// comma that ended the one before (pieces end at separators). `None` at the first number
/// that is not so, and the one-by-one reading checks the array.
fn numbers_of_tight_piece<T: Send + 'static>(
    text: &[u8],
    range: Range<usize>,
    scan: ScanNumber<T>,
) -> Option<Vec<T>> {
    let mut numbers = split::scratch::take(range.len());
    let mut at = range.start;
    if at > 0 {
        if text[at] != b',' {
            return None;
        }
        at += 1;
    }
    loop {
        if !matches!(text.get(at), Some(b'-' | b'0'..=b'9')) {
            return None;
        }
        let (value, end) = scan(&text[..range.end], at)?;
        // The array's last number ends the text; any other is followed by its comma.
        if !tight_number(text, at, end, end == text.len()) {
            return None;
        }
        numbers.push(value);
        if end == range.end {
            return Some(numbers);
        }
        at = end + 1;
    }
}

/// The numbers in `text[range]`, each read as [`Elements::next_number`] reads it; `None`
/// at the first element that it would not read.
///
/// [`Elements::next_number`]: super::tree::Elements::next_number
fn numbers_of_piece<T: Send + 'static>(
    text: &[u8],
    range: Range<usize>,
    scan: ScanNumber<T>,
) -> Option<Vec<T>> {
    let text = &text[..range.end];
    let mut numbers = split::scratch::take(range.len());
    let mut at = range.start;
    loop {
        while at < text.len() && is_separator(text[at]) {
            at += 1;
        }
        if at == text.len() {
            return Some(numbers);
        }
        if !matches!(text[at], b'-' | b'0'..=b'9') {
            return None;
        }
        let (value, end) = scan(text, at)?;
        numbers.push(value);
        at = end;
    }
}

fn strings(tree: &Tree, i: usize, ty: FieldType) -> Result<Vec<String>, ValueError> {
    match tree.kind(i) {
        // A lone string for an MFString is taken as a list of one.
        Kind::String => Ok(vec![tree.str(i).into_owned()]),
        Kind::Array if ty.is_mf() => {
            let mut values = Vec::with_capacity(tree.item(i).len as usize);
            for (index, e) in tree.elements(i).enumerate() {
                if tree.kind(e) != Kind::String {
                    return Err(element_error(tree, e, ty, index));
                }
                values.push(tree.str(e).into_owned());
            }
            Ok(values)
        }
        _ => Err(wrong_kind(tree, i, ty)),
    }
}

fn images(tree: &Tree, i: usize, ty: FieldType) -> Result<Vec<Image>, ValueError> {
    if tree.kind(i) != Kind::Array {
        return Err(wrong_kind(tree, i, ty));
    }
    let mut elements = tree.elements(i);
    let mut images = Vec::new();
    while elements.len() > 0 {
        let mut header = [0i32; 3];
        // From the image's first element to the last one read.
        let mut header_span = (0, 0);
        for (h, slot) in header.iter_mut().enumerate() {
            let Some(e) = elements.next() else {
                let what = ["width", "height", "components"][h];
                return Err(ValueError::new(
                    header_span,
                    format!("{ty} needs width, height and components before its pixels; {what} is missing"),
                ));
            };
            let (start, end) = tree.full_span(e);
            header_span = (if h == 0 { start } else { header_span.0 }, end);
            *slot = image_int(tree, e, ty, true, images.len())? as i32;
        }
        let [width, height, components] = header;
        let remaining = elements.len();
        let take = if ty.is_mf() {
            // The size says where the next image starts; take what is there if the data
            // ends first.
            let declared = (width.max(0) as u64).saturating_mul(height.max(0) as u64);
            declared.min(remaining as u64) as usize
        } else {
            remaining
        };
        let mut pixels = Vec::with_capacity(take);
        for e in elements.by_ref().take(take) {
            pixels.push(image_int(tree, e, ty, false, images.len())? as u32);
        }
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
        return Err(ValueError::new(
            tree.full_span(i),
            format!("{ty} takes [width, height, components, pixel…], e.g. [0, 0, 0]; found an empty array"),
        ));
    }
    Ok(images)
}

/// An image size (`header`, an `i32`) or pixel (up to 0xFFFFFFFF; negative values down to
/// −2^31 taken as their 32-bit pattern), as an `i64`.
fn image_int(
    tree: &Tree,
    e: ValueRef,
    ty: FieldType,
    header: bool,
    image: usize,
) -> Result<i64, ValueError> {
    let what = if header { "size" } else { "pixel value" };
    let error = |message: String| {
        let error = ValueError::new(tree.full_span(e), message);
        if ty.is_mf() {
            error.index(image)
        } else {
            error
        }
    };
    let item = tree.item(e);
    if item.kind != Kind::Number {
        return Err(error(format!(
            "{ty} takes whole numbers, found {} as a {what}",
            describe(tree, e)
        )));
    }
    let text = tree.raw(e);
    let v = if item.flags & NOT_INTEGER == 0 {
        // Saturated like `whole_number`: too long is out of range, not malformed.
        Some(text.parse::<i64>().unwrap_or(if text.starts_with('-') {
            i64::MIN
        } else {
            i64::MAX
        }))
    } else {
        whole_number(text.as_bytes())
    };
    let Some(v) = v else {
        return Err(error(format!(
            "{ty} takes whole numbers, found {text} as a {what}"
        )));
    };
    let (min, max) = if header {
        (i32::MIN as i64, i32::MAX as i64)
    } else {
        (i32::MIN as i64, u32::MAX as i64)
    };
    if v < min || v > max {
        let limit = if header {
            "at most 2147483647"
        } else {
            "at most 4294967295 (0xFFFFFFFF)"
        };
        return Err(error(format!(
            "{text} is out of range for an {ty} {what} ({limit})"
        )));
    }
    Ok(if !header && v < 0 {
        (v as i32 as u32) as i64
    } else {
        v
    })
}

#[cfg(test)]
mod tests {
    use super::super::tree::parse;
    use super::*;

    fn conv(json: &str, ty: FieldType) -> Result<Value, ValueError> {
        let tree = parse(json).unwrap();
        convert(&tree, 0, ty)
    }

    fn err(json: &str, ty: FieldType) -> ValueError {
        conv(json, ty).expect_err(json)
    }

    #[test]
    fn booleans() {
        assert_eq!(
            conv("true", FieldType::SFBool),
            Ok(Value::Bools(vec![true]))
        );
        assert_eq!(
            conv("[true, false]", FieldType::MFBool),
            Ok(Value::Bools(vec![true, false]))
        );
        let e = err("\"true\"", FieldType::SFBool);
        assert_eq!(
            e.message,
            "SFBool takes a boolean, found the string \"true\""
        );
        assert!(e.help.unwrap().contains("without quotes"));
        assert_eq!(e.span, (0, 6));
        let e = err("[true, 1]", FieldType::MFBool);
        assert_eq!(e.span, (7, 8));
        assert_eq!(e.index, Some(1));
    }

    #[test]
    fn int32s() {
        assert_eq!(conv("-7", FieldType::SFInt32), Ok(Value::Int32s(vec![-7])));
        assert_eq!(
            conv("1e2", FieldType::SFInt32),
            Ok(Value::Int32s(vec![100]))
        );
        assert_eq!(conv("2.0", FieldType::SFInt32), Ok(Value::Int32s(vec![2])));
        assert_eq!(
            conv("[0, 1, 2, -1, -2147483648, 2147483647]", FieldType::MFInt32),
            Ok(Value::Int32s(vec![0, 1, 2, -1, i32::MIN, i32::MAX]))
        );
        let e = err("1.5", FieldType::SFInt32);
        assert_eq!(
            e.message,
            "SFInt32 takes whole numbers: whole numbers only, found 1.5"
        );
        let e = err("[1, 2, 2147483648]", FieldType::MFInt32);
        assert!(e.message.contains("out of range"), "{}", e.message);
        assert_eq!(e.span, (7, 17));
        assert_eq!(e.index, Some(2));
        assert!(err("99999999999999999999999", FieldType::SFInt32)
            .message
            .contains("out of range"));
        assert!(err("1e300", FieldType::SFInt32)
            .message
            .contains("out of range"));
        assert!(err("1e400", FieldType::SFInt32)
            .message
            .contains("out of range"));
        // Whole or not is decided on the digits, not on the nearest f64.
        for text in ["1.00000000000000000001", "2147483647.0000000001", "1e-400"] {
            let e = err(text, FieldType::SFInt32);
            assert!(
                e.message.contains("whole numbers only"),
                "{text}: {}",
                e.message
            );
        }
        assert_eq!(
            conv("21474836470e-1", FieldType::SFInt32),
            Ok(Value::Int32s(vec![i32::MAX]))
        );
        assert_eq!(
            conv("-0.21474836480000e10", FieldType::SFInt32),
            Ok(Value::Int32s(vec![i32::MIN]))
        );
    }

    #[test]
    fn whole_numbers_from_their_digits() {
        let whole = |t: &str| whole_number(t.as_bytes());
        assert_eq!(whole("0"), Some(0));
        assert_eq!(whole("-0.0e5"), Some(0));
        assert_eq!(whole("12.50e1"), Some(125));
        assert_eq!(whole("12.51e1"), None);
        assert_eq!(whole("1e18"), Some(1_000_000_000_000_000_000));
        assert_eq!(whole("1e99999999999999999999"), Some(i64::MAX));
        assert_eq!(whole("-1e99999999999999999999"), Some(-i64::MAX));
        assert_eq!(whole("0e99999999999999999999"), Some(0));
        assert_eq!(whole("1e-99999999999999999999"), None);
        assert_eq!(whole("0.000e-99999999999999999999"), Some(0));
        assert_eq!(whole("100e-2"), Some(1));
        assert_eq!(whole("101e-2"), None);
    }

    #[test]
    fn floats_round_once_and_overflow_to_infinity() {
        assert_eq!(
            conv("0.1", FieldType::SFFloat),
            Ok(Value::Floats(vec![0.1f32]))
        );
        assert_eq!(
            conv("1e39", FieldType::SFFloat),
            Ok(Value::Floats(vec![f32::INFINITY]))
        );
        assert_eq!(
            conv("-1e39", FieldType::SFFloat),
            Ok(Value::Floats(vec![f32::NEG_INFINITY]))
        );
        assert_eq!(
            conv("1e39", FieldType::SFDouble),
            Ok(Value::Doubles(vec![1e39]))
        );
        assert_eq!(
            conv("1e-50", FieldType::SFFloat),
            Ok(Value::Floats(vec![0.0]))
        );
        assert_eq!(
            conv("-0", FieldType::SFFloat),
            Ok(Value::Floats(vec![-0.0]))
        );
        // Correctly rounded directly to f32 (not through f64).
        assert_eq!(
            conv("1.00000005960464477539062501", FieldType::SFFloat),
            Ok(Value::Floats(vec![1.000_000_1_f32]))
        );
        assert_eq!(
            conv("0.1", FieldType::SFTime),
            Ok(Value::Doubles(vec![0.1]))
        );
    }

    #[test]
    fn vectors_check_arity() {
        assert_eq!(
            conv("[1, 0, 0]", FieldType::SFColor),
            Ok(Value::Floats(vec![1.0, 0.0, 0.0]))
        );
        let e = err("[1, 0]", FieldType::SFColor);
        assert_eq!(e.message, "SFColor takes 3 numbers, found 2");
        assert_eq!(e.span, (0, 6));
        let e = err("[1, 0, 0, 1]", FieldType::SFColor);
        assert_eq!(e.message, "SFColor takes 3 numbers, found 4");
        assert_eq!(e.span, (10, 11));
        assert_eq!(
            err("[]", FieldType::SFVec3f).message,
            "SFVec3f takes 3 numbers, found none"
        );
        assert_eq!(
            conv("[0,0,0, 1,0,0]", FieldType::MFVec3f),
            Ok(Value::Floats(vec![0.0, 0.0, 0.0, 1.0, 0.0, 0.0]))
        );
        assert_eq!(conv("[]", FieldType::MFVec3f), Ok(Value::Floats(vec![])));
        let e = err("[0,0,0, 1,0]", FieldType::MFVec3f);
        assert_eq!(e.message, "MFVec3f takes a multiple of 3 numbers, found 5");
        assert_eq!(e.span, (8, 11));
        assert_eq!(e.index, Some(1));
        assert_eq!(
            conv("[0,0,1,3.14]", FieldType::SFRotation).unwrap().len(),
            4
        );
        assert_eq!(
            conv("[1,2,3]", FieldType::SFVec3d),
            Ok(Value::Doubles(vec![1.0, 2.0, 3.0]))
        );
        assert_eq!(
            conv(&format!("[{}]", ["1"; 16].join(",")), FieldType::SFMatrix4f)
                .unwrap()
                .len(),
            16
        );
    }

    #[test]
    fn json_slips_are_syntax_errors() {
        let e = err("\"1\"", FieldType::SFFloat);
        assert_eq!(e.message, "SFFloat takes a number, found the string \"1\"");
        assert_eq!(
            e.help.as_deref(),
            Some("JSON numbers are written without quotes")
        );
        let e = err("\"1 0 0\"", FieldType::SFColor);
        assert!(e
            .message
            .starts_with("SFColor takes an array of 3 numbers, found the string"));
        assert!(e.help.is_some());
        let e = err("{\"a\": 1}", FieldType::MFFloat);
        assert_eq!(
            e.message,
            "MFFloat takes an array of numbers, found an object"
        );
        assert_eq!(
            err("null", FieldType::SFVec3f).message,
            "SFVec3f takes an array of 3 numbers, found null"
        );
        let e = err("[1, \"2\", 3]", FieldType::SFVec3f);
        assert_eq!(e.message, "SFVec3f takes numbers, found the string \"2\"");
        assert_eq!(e.span, (4, 7));
        let e = err("[[0,0,0],[1,0,0]]", FieldType::MFVec3f);
        assert!(e.help.unwrap().contains("flat array"));
        let e = err("[1]", FieldType::SFFloat);
        assert!(e.help.unwrap().contains("drop the brackets"));
        assert_eq!(
            err("5", FieldType::SFString).message,
            "SFString takes a string, found the number 5"
        );
    }

    #[test]
    fn strings_and_lone_strings() {
        assert_eq!(
            conv("\"a\\\"b\"", FieldType::SFString),
            Ok(Value::Strings(vec!["a\"b".into()]))
        );
        assert_eq!(
            conv("[\"EXAMINE\", \"ANY\"]", FieldType::MFString),
            Ok(Value::Strings(vec!["EXAMINE".into(), "ANY".into()]))
        );
        assert_eq!(
            conv("\"x.png\"", FieldType::MFString),
            Ok(Value::Strings(vec!["x.png".into()]))
        );
        assert_eq!(conv("[]", FieldType::MFString), Ok(Value::Strings(vec![])));
        let e = err("[\"a\", 1]", FieldType::MFString);
        assert_eq!(e.message, "MFString takes strings, found the number 1");
        assert_eq!(e.index, Some(1));
        assert!(err("[\"a\"]", FieldType::SFString)
            .message
            .contains("found an array"));
    }

    #[test]
    fn images() {
        let v = conv("[2, 1, 3, 16711680, 255]", FieldType::SFImage).unwrap();
        assert_eq!(
            v,
            Value::Images(vec![Image {
                width: 2,
                height: 1,
                components: 3,
                pixels: vec![0xFF0000, 0xFF]
            }])
        );
        let v = conv("[1, 1, 4, 4294967295, 1, 2, 1, -1, 2]", FieldType::MFImage).unwrap();
        let images = v.as_images().unwrap();
        assert_eq!(images.len(), 2);
        assert_eq!(images[0].pixels, vec![u32::MAX]);
        assert_eq!(images[1].pixels, vec![u32::MAX, 2]);
        assert_eq!(conv("[0, 0, 0]", FieldType::SFImage).unwrap().len(), 1);
        assert_eq!(conv("[]", FieldType::MFImage), Ok(Value::Images(vec![])));
        assert!(err("[]", FieldType::SFImage)
            .message
            .contains("empty array"));
        assert!(err("[1, 1]", FieldType::SFImage)
            .message
            .contains("components is missing"));
        assert!(err("[1, 1, 1, 0.5]", FieldType::SFImage)
            .message
            .contains("whole numbers"));
        assert!(err("[1, 1, 1, 4294967296]", FieldType::SFImage)
            .message
            .contains("out of range"));
        assert!(err("\"1 1 1 0\"", FieldType::SFImage)
            .message
            .contains("found the string"));
    }

    #[test]
    fn node_types_are_not_values() {
        assert!(err("[]", FieldType::MFNode).message.contains("take nodes"));
    }

    /// The text at an error's span.
    fn at<'a>(json: &'a str, e: &ValueError) -> &'a str {
        &json[e.span.0..e.span.1]
    }

    #[test]
    fn errors_inside_number_arrays_point_at_the_element() {
        // Elements of arrays have no items of their own: the spans come from the text.
        let cases: &[(&str, FieldType, &str, Option<usize>, &str)] = &[
            (
                "[0, 0, 0,\n 1, \"1\", 0]",
                FieldType::MFVec3f,
                "\"1\"",
                Some(1),
                "MFVec3f takes numbers, found the string \"1\"",
            ),
            (
                "[0,0,0, [1,0,0]]",
                FieldType::MFVec3f,
                "[1,0,0]",
                Some(1),
                "MFVec3f takes numbers, found an array",
            ),
            (
                "[0,0,0, 1,0,0, {\"x\": 1}]",
                FieldType::MFVec3f,
                "{\"x\": 1}",
                Some(2),
                "MFVec3f takes numbers, found an object",
            ),
            (
                "[ 1 ,\t2 , null ]",
                FieldType::SFVec3f,
                "null",
                None,
                "SFVec3f takes numbers, found null",
            ),
            (
                "[0, 1, 2, 3.5, 4]",
                FieldType::MFInt32,
                "3.5",
                Some(3),
                "MFInt32 takes whole numbers: whole numbers only, found 3.5",
            ),
            (
                "[0, -1, -2147483649, 4]",
                FieldType::MFInt32,
                "-2147483649",
                Some(2),
                "MFInt32 takes whole numbers: -2147483649 is out of range (-2147483648 to 2147483647)",
            ),
            (
                "[1, 0, false, 1]",
                FieldType::SFRotation,
                "false",
                None,
                "SFRotation takes numbers, found `false`",
            ),
            (
                "[\"a\\\"b\", 1]",
                FieldType::MFString,
                "1",
                Some(1),
                "MFString takes strings, found the number 1",
            ),
            (
                "[true,false , \"false\"]",
                FieldType::MFBool,
                "\"false\"",
                Some(2),
                "MFBool takes booleans, found the string \"false\"",
            ),
            (
                "[1, 1, 3, 255, 2.5e0]",
                FieldType::MFImage,
                "2.5e0",
                Some(1),
                "MFImage takes whole numbers, found 2.5e0 as a size",
            ),
            (
                "[0,0,0, 1,0,0, 1 ]",
                FieldType::MFVec3f,
                "1",
                Some(2),
                "MFVec3f takes a multiple of 3 numbers, found 7",
            ),
            (
                "[1, 2, 3, 4,\n 5]",
                FieldType::SFVec3f,
                "4,\n 5",
                None,
                "SFVec3f takes 3 numbers, found 5",
            ),
        ];
        for &(json, ty, text, index, message) in cases {
            let e = err(json, ty);
            assert_eq!(at(json, &e), text, "{json} as {ty}");
            assert_eq!(e.index, index, "{json} as {ty}");
            assert_eq!(e.message, message, "{json} as {ty}");
        }
        let e = err("[0, 0, 0, \"1 2\"]", FieldType::MFFloat);
        assert_eq!(
            e.help.as_deref(),
            Some("JSON numbers are written without quotes")
        );
        let e = err("[0,0,0, [1,0,0]]", FieldType::MFVec3f);
        assert!(e.help.unwrap().contains("flat array"));
    }

    #[test]
    fn numbers_read_in_one_pass_equal_numbers_read_one_by_one() {
        // Each token alone (as a single value, read by the per-token readers) and as every
        // element of an array (read in one pass from the array's text) gives one value.
        let floats = [
            "0",
            "-0",
            "0.1",
            "-1.5E-3",
            "1e39",
            "-1e400",
            "1e-50",
            "3.4028235e38",
            "1.00000005960464477539062501",
            "123456789012345678901234567890",
            "0.000000000000000000000000000000000000000000001401298464324817",
        ];
        let array = format!("[{}]", floats.join(" ,\n\t"));
        let Value::Floats(f32s) = conv(&array, FieldType::MFFloat).unwrap() else {
            panic!("floats")
        };
        let Value::Doubles(f64s) = conv(&array, FieldType::MFDouble).unwrap() else {
            panic!("doubles")
        };
        for (k, token) in floats.iter().enumerate() {
            assert_eq!(
                f32s[k].to_bits(),
                conv(token, FieldType::SFFloat)
                    .unwrap()
                    .as_floats()
                    .unwrap()[0]
                    .to_bits(),
                "{token}"
            );
            assert_eq!(
                f64s[k].to_bits(),
                conv(token, FieldType::SFDouble)
                    .unwrap()
                    .as_doubles()
                    .unwrap()[0]
                    .to_bits(),
                "{token}"
            );
        }
        // Integers the one-pass reader refuses (exponents, fractions of zero) are read one
        // by one, in place.
        assert_eq!(
            conv(
                "[0,-0, 7, 1e2, 2.0, -2147483648, 2147483647, -5]",
                FieldType::MFInt32
            ),
            Ok(Value::Int32s(vec![0, 0, 7, 100, 2, i32::MIN, i32::MAX, -5]))
        );
        assert_eq!(
            conv("[ ]", FieldType::MFInt32),
            Ok(Value::Int32s(Vec::new()))
        );
    }
}
