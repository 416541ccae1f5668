//! A strict (RFC 8259) single-pass JSON scanner that keeps positions.
//!
//! `serde_json::Value` forgets where things were; the checker must point at the key or
//! value at fault. [`parse`] reads the text once, left to right, with an explicit stack
//! (no recursion, so deep input cannot overflow the thread's stack; nesting deeper than
//! [`MAX_DEPTH`] is an error) into a flat, pre-order [`Tree`] of [`Item`]s: every object,
//! array, object key and member value with its byte span. Strings and numbers are not
//! converted here: a string borrows the input unless it has escapes, and a number is read
//! from its text by whoever knows its type (so an SFFloat is rounded once, straight to
//! `f32`).
//!
//! Scalars (numbers, strings, literals) that are elements of an array get no item: they
//! are nearly all of a large scene (every number of every coordinate and index array),
//! and an item each would take several times the input's size. [`Tree::elements`] reads
//! them back from the text, which the scanner has checked, with their exact spans; an
//! array's containers are items as any other, in order among its scalars.
//!
//! Duplicate keys are not an error in the grammar: both members stay in the tree, in
//! document order, for the reader to report.

use std::borrow::Cow;
use std::sync::atomic::{AtomicBool, Ordering};

use crate::model::text::number::leading_digits;
use crate::parse::behind::{Pass, Progress};

/// Nesting deeper than this (arrays and objects) is refused.
pub const MAX_DEPTH: usize = crate::limits::MAX_JSON_NESTING;

#[derive(Copy, Clone, Debug, PartialEq, Eq)]
pub enum Kind {
    Null,
    True,
    False,
    Number,
    String,
    Array,
    Object,
    /// An object member's key; the member's value is the next item.
    Key,
}

/// The string had at least one backslash escape.
pub const ESCAPED: u8 = 1;
/// The number has a fraction or an exponent.
pub const NOT_INTEGER: u8 = 2;
/// An array that [`parse_deferring`] skipped: its text is digits, `-`, `.` and commas, and
/// its elements are checked against the grammar when they are read (see [`Deferred`]).
pub const UNCHECKED: u8 = 4;

/// One value or key. Strings and keys span their content without the quotes; numbers
/// and literals their token; arrays and objects everything from the bracket to its mate.
#[derive(Copy, Clone, Debug, PartialEq, Eq)]
pub struct Item {
    pub kind: Kind,
    pub flags: u8,
    pub start: u32,
    pub end: u32,
    /// The index just past this item's subtree: its next sibling item, for a value in an
    /// array or an object member's key. For a key, the item after its value's subtree.
    /// 0 for a scalar read back from an array.
    pub next: u32,
    /// Elements of an array (scalars included), members of an object.
    pub len: u32,
}

/// A value of the document: an item of the tree (by index), or a scalar element of an
/// array, which has no item of its own and is read back from the text as one.
#[derive(Copy, Clone, Debug, PartialEq, Eq)]
pub enum ValueRef {
    Item(usize),
    Scalar(Item),
}

impl From<usize> for ValueRef {
    fn from(i: usize) -> ValueRef {
        ValueRef::Item(i)
    }
}

/// The scanned document: items in pre-order. An object is followed by, for each member,
/// its key and then its value's subtree; an array by the subtrees of its elements that
/// are arrays or objects.
pub struct Tree<'s> {
    pub src: &'s str,
    pub items: Vec<Item>,
    pub deferred: Deferred,
}

/// The arrays [`parse_deferring`] skipped without checking their numbers. Whoever reads
/// one checks it: the number readers ([`Elements::next_number`] and the pieces of a long
/// array) check each number's shape and its comma as they read it, anything else checks
/// the whole array with the scanner first. [`Tree::deferred_are_json`] checks those no
/// reader finished.
#[derive(Default)]
pub struct Deferred {
    /// Their item indices, ascending.
    arrays: Vec<u32>,
    /// Each found to be JSON.
    checked: Box<[AtomicBool]>,
    /// One was found not to be JSON.
    broken: AtomicBool,
}

/// A syntax error at a byte offset.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Error {
    pub at: usize,
    /// Bytes the error covers (0 at the end of the input).
    pub len: usize,
    pub message: String,
}

impl<'s> Tree<'s> {
    /// The item of a value: its own, or the one read back for a scalar element.
    #[inline]
    pub fn item(&self, v: impl Into<ValueRef>) -> Item {
        match v.into() {
            ValueRef::Item(i) => self.items[i],
            ValueRef::Scalar(item) => item,
        }
    }

    #[inline]
    pub fn kind(&self, v: impl Into<ValueRef>) -> Kind {
        self.item(v).kind
    }

    /// The index past item `i`'s subtree.
    pub fn next(&self, i: usize) -> usize {
        self.items[i].next as usize
    }

    /// The value's span: for strings and keys, the content without the quotes.
    #[inline]
    pub fn span(&self, v: impl Into<ValueRef>) -> (usize, usize) {
        let it = self.item(v);
        (it.start as usize, it.end as usize)
    }

    /// The value's whole token: strings and keys with their quotes.
    pub fn full_span(&self, v: impl Into<ValueRef>) -> (usize, usize) {
        let it = self.item(v);
        match it.kind {
            Kind::String | Kind::Key => (it.start as usize - 1, it.end as usize + 1),
            _ => (it.start as usize, it.end as usize),
        }
    }

    /// The value's text as written (for strings and keys: between the quotes, escapes
    /// kept).
    pub fn raw(&self, v: impl Into<ValueRef>) -> &'s str {
        let (s, e) = self.span(v);
        &self.src[s..e]
    }

    /// [`Tree::raw`] as bytes (no character-boundary checks: for numbers).
    #[inline]
    pub fn raw_bytes(&self, v: impl Into<ValueRef>) -> &'s [u8] {
        let (s, e) = self.span(v);
        &self.src.as_bytes()[s..e]
    }

    /// The whole token's text as written, quotes included: the JSON text of the value.
    pub fn raw_full(&self, v: impl Into<ValueRef>) -> &'s str {
        let (s, e) = self.full_span(v);
        &self.src[s..e]
    }

    /// A string's or key's text, unescaped. Borrowed when it has no escapes.
    pub fn str(&self, v: impl Into<ValueRef>) -> Cow<'s, str> {
        let v = v.into();
        let raw = self.raw(v);
        if self.item(v).flags & ESCAPED == 0 {
            Cow::Borrowed(raw)
        } else {
            // The scanner checked the escapes (surrogates paired), so this cannot fail;
            // keep the raw text if it ever did.
            let quoted = self.raw_full(v);
            Cow::Owned(serde_json::from_str::<String>(quoted).unwrap_or_else(|_| raw.to_string()))
        }
    }

    /// The item index of `v` when it is an object.
    pub fn object(&self, v: ValueRef) -> Option<usize> {
        match v {
            ValueRef::Item(i) if self.items[i].kind == Kind::Object => Some(i),
            _ => None,
        }
    }

    /// The members of object `i` as (key, value) index pairs, in document order.
    pub fn members(&self, i: usize) -> Members<'_, 's> {
        debug_assert_eq!(self.items[i].kind, Kind::Object);
        Members {
            tree: self,
            cursor: i + 1,
            end: self.next(i),
        }
    }

    /// The elements of array `i`, in order.
    pub fn elements(&self, i: usize) -> Elements<'_, 's> {
        let array = &self.items[i];
        Elements {
            tree: self,
            array: i,
            tight: self.is_unchecked(i),
            text: self.array_text(i),
            base: array.start as usize + 1,
            at: 0,
            container: i + 1,
            left: array.len,
        }
    }

    /// The text of array `i` between its brackets.
    pub fn array_text(&self, i: usize) -> &'s [u8] {
        let array = &self.items[i];
        debug_assert_eq!(array.kind, Kind::Array);
        &self.src.as_bytes()[array.start as usize + 1..array.end as usize - 1]
    }

    /// The value of the first member of object `i` whose key is `key` (keys compared as
    /// written: X3D keys have no escapes).
    pub fn get(&self, i: usize, key: &str) -> Option<(usize, usize)> {
        self.members(i).find(|&(k, _)| self.key_is(k, key))
    }

    /// Whether key (or string) `k` is `text`.
    pub fn key_is(&self, k: usize, text: &str) -> bool {
        if self.items[k].flags & ESCAPED == 0 {
            self.raw(k) == text
        } else {
            self.str(k) == text
        }
    }

    /// Whether array `i` was skipped by the scanner and nobody has checked it yet: its
    /// numbers are to be read with [`tight_number`] or after [`Tree::check_deferred`].
    pub fn is_unchecked(&self, i: usize) -> bool {
        self.items[i].flags & UNCHECKED != 0
            && !self.deferred.checked[self.deferred_slot(i)].load(Ordering::Relaxed)
    }

    fn deferred_slot(&self, i: usize) -> usize {
        self.deferred
            .arrays
            .binary_search(&(i as u32))
            .expect("an UNCHECKED array is in the deferred list")
    }

    /// Records that skipped array `i` was read to its end by the number readers, each
    /// number and comma checked.
    pub fn mark_checked(&self, i: usize) {
        self.deferred.checked[self.deferred_slot(i)].store(true, Ordering::Relaxed);
    }

    /// Checks skipped array `i` with the scanner (once): whether it is JSON. When it is
    /// not, the tree is not the document's and [`Tree::deferred_are_json`] says so.
    pub fn check_deferred(&self, i: usize) -> bool {
        let slot = self.deferred_slot(i);
        if self.deferred.checked[slot].load(Ordering::Relaxed) {
            return true;
        }
        let (start, end) = self.span(i);
        // The array holds no brackets, quotes or objects: on its own it is the same text.
        let json = parse(&self.src[start..end]).is_ok();
        if json {
            self.deferred.checked[slot].store(true, Ordering::Relaxed);
        } else {
            self.deferred.broken.store(true, Ordering::Relaxed);
        }
        json
    }

    /// Whether every array [`parse_deferring`] skipped is JSON, checking those no reader
    /// did. When not, the text has a syntax error that [`parse`] reports.
    pub fn deferred_are_json(&self) -> bool {
        !self.deferred.broken.load(Ordering::Relaxed)
            && self
                .deferred
                .arrays
                .iter()
                .all(|&i| self.check_deferred(i as usize))
    }
}

/// The shape a number of a skipped array must have besides what the number reader `scan`
/// accepted in `text[at..end]`, `end` being where that reader stopped: a JSON number
/// (`-?(0|[1-9][0-9]*)(\.[0-9]+)?`: the array has no exponents) followed by a comma, or
/// by the end of the array when it is the `last`. The reader accepted digits with at most
/// one `.` after an optional sign; JSON also wants a digit first, no leading zero and a
/// digit after the `.`.
#[inline(always)]
pub fn tight_number(text: &[u8], at: usize, end: usize, last: bool) -> bool {
    let int_start = at + usize::from(text[at] == b'-');
    let first = text.get(int_start).copied().unwrap_or(0);
    first.is_ascii_digit()
        && !(first == b'0' && text.get(int_start + 1).is_some_and(u8::is_ascii_digit))
        && text[end - 1] != b'.'
        && if last {
            end == text.len()
        } else {
            text.get(end) == Some(&b',')
        }
}

pub struct Members<'t, 's> {
    tree: &'t Tree<'s>,
    cursor: usize,
    end: usize,
}

impl Iterator for Members<'_, '_> {
    type Item = (usize, usize);

    fn next(&mut self) -> Option<(usize, usize)> {
        if self.cursor >= self.end {
            return None;
        }
        let key = self.cursor;
        let value = key + 1;
        self.cursor = self.tree.next(value);
        Some((key, value))
    }
}

/// The elements of an array: its arrays and objects are the tree's items, its scalars are
/// read back from the text. The scanner checked that text, so only the ends of tokens are
/// looked for here.
pub struct Elements<'t, 's> {
    tree: &'t Tree<'s>,
    /// The array's item.
    array: usize,
    /// The array was skipped by the scanner and is not checked yet: each number is read
    /// with its comma, as [`tight_number`] says, until one is not, when the whole array
    /// is checked.
    tight: bool,
    /// The array's text between its brackets.
    text: &'s [u8],
    /// The offset of `text` in the source.
    base: usize,
    /// Where in `text` to look for the next element: after the previous one.
    at: usize,
    /// The item of the next element that is an array or object.
    container: usize,
    /// Elements not read yet.
    left: u32,
}

/// A reader of one number in a larger text, as the `scan_*` functions of
/// [`crate::model::text::number`]: `scan(text, at)` gives the number starting at `at` and the
/// offset where it ends, or `None` when it refuses the number.
pub type ScanNumber<T> = fn(&[u8], usize) -> Option<(T, usize)>;

impl<'s> Elements<'_, 's> {
    /// The offset in `text` of the next element, past whitespace and the comma before it.
    #[inline(always)]
    fn skip_separators(&self) -> usize {
        let mut at = self.at;
        while let Some(b' ' | b'\n' | b'\r' | b'\t' | b',') = self.text.get(at) {
            at += 1;
        }
        at
    }

    /// Reads the next element in one pass over its text when it is a number that `scan`
    /// accepts. `scan` is given the array's text between its brackets, where the number
    /// ends at a separator (`,`, whitespace) or at the end, as the `scan_*` readers of
    /// [`crate::model::text::number`] expect. `None`, leaving the element for
    /// [`Iterator::next`], when it is not a number or `scan` refuses it, or when there are
    /// no more elements.
    #[inline(always)]
    pub fn next_number<T>(&mut self, scan: ScanNumber<T>) -> Option<T> {
        if self.left == 0 {
            return None;
        }
        let at = if self.tight {
            self.at
        } else {
            self.skip_separators()
        };
        if !matches!(self.text.get(at), Some(b'-' | b'0'..=b'9')) {
            return None;
        }
        let (value, end) = scan(self.text, at)?;
        if self.tight {
            let last = self.left == 1;
            if !tight_number(self.text, at, end, last) {
                return None;
            }
            // Past the comma.
            self.at = end + usize::from(!last);
        } else {
            self.at = end;
        }
        self.left -= 1;
        Some(value)
    }
}

impl Iterator for Elements<'_, '_> {
    type Item = ValueRef;

    fn next(&mut self) -> Option<ValueRef> {
        if self.tight {
            self.tight = false;
            if self.left == 0 {
                // Every element was read by `next_number`, each with its comma.
                self.tree.mark_checked(self.array);
            } else if !self.tree.check_deferred(self.array) {
                self.left = 0;
            }
        }
        if self.left == 0 {
            return None;
        }
        self.left -= 1;
        let s = self.text;
        let at = self.skip_separators();
        // The element's kind, flags and span in `text`, and where it ends there.
        let (kind, flags, start, end, after) = match s[at] {
            b'{' | b'[' => {
                let i = self.container;
                self.container = self.tree.next(i);
                self.at = self.tree.items[i].end as usize - self.base;
                return Some(ValueRef::Item(i));
            }
            b'"' => {
                let mut i = at + 1;
                let mut flags = 0;
                loop {
                    match s[i] {
                        b'"' => break,
                        b'\\' => {
                            flags = ESCAPED;
                            i += 2;
                        }
                        _ => i += 1,
                    }
                }
                (Kind::String, flags, at + 1, i, i + 1)
            }
            b't' => (Kind::True, 0, at, at + 4, at + 4),
            b'f' => (Kind::False, 0, at, at + 5, at + 5),
            b'n' => (Kind::Null, 0, at, at + 4, at + 4),
            _ => {
                // After the first character, `.`, `e`, `E`, `+` and `-` only occur in
                // numbers with a fraction or an exponent.
                let mut i = at + 1;
                let mut flags = 0;
                while let Some(&b) = s.get(i) {
                    match NUMBER_CLASS[b as usize] {
                        DIGIT => {}
                        DOT | EXP_SIGN => flags = NOT_INTEGER,
                        _ => break,
                    }
                    i += 1;
                }
                (Kind::Number, flags, at, i, i)
            }
        };
        self.at = after;
        Some(ValueRef::Scalar(Item {
            kind,
            flags,
            start: (self.base + start) as u32,
            end: (self.base + end) as u32,
            next: 0,
            len: 0,
        }))
    }

    fn size_hint(&self) -> (usize, Option<usize>) {
        (self.left as usize, Some(self.left as usize))
    }
}

impl ExactSizeIterator for Elements<'_, '_> {}

/// What the scanner expects next.
#[derive(Copy, Clone, PartialEq, Eq)]
enum State {
    /// A value (at the top, after `[`, `,` in an array or `:`).
    Value,
    /// The first key of an object or its `}` (after `{`).
    FirstKey,
    /// A key (after `,` in an object).
    Key,
    /// `,` or the closing bracket of the innermost container, or the end at the top.
    AfterValue,
}

const DIGIT: u8 = 1;
const DOT: u8 = 2;
/// `e`, `E`, `+`, `-`: parts of an exponent.
const EXP_SIGN: u8 = 4;
/// Other ASCII letters and `_`: never right after a number.
const LETTER: u8 = 8;

/// What each byte can be in a number.
static NUMBER_CLASS: [u8; 256] = {
    let mut table = [0u8; 256];
    let mut b = 0;
    while b < 256 {
        let c = b as u8;
        table[b] = if c.is_ascii_digit() {
            DIGIT
        } else if c == b'.' {
            DOT
        } else if matches!(c, b'e' | b'E' | b'+' | b'-') {
            EXP_SIGN
        } else if c.is_ascii_alphabetic() || c == b'_' {
            LETTER
        } else {
            0
        };
        b += 1;
    }
    table
};

/// Reads `src` as one JSON text. A leading UTF-8 byte order mark is skipped.
pub fn parse(src: &str) -> Result<Tree<'_>, Error> {
    parse_with_progress(src, &())
}

/// [`parse`], telling `progress` how far the scanner has got.
pub fn parse_with_progress<'s>(src: &'s str, progress: &dyn Progress) -> Result<Tree<'s>, Error> {
    scan(src, progress, false)
}

/// [`parse_with_progress`], but an array of digits, `-`, `.` and commas only (most of a
/// large scene: coordinates and indices written without spaces) is skipped to its `]`
/// and marked [`UNCHECKED`], for its reader to check as it reads its numbers (the
/// grammar was a second pass over them). The tree is the document's only if
/// [`Tree::deferred_are_json`] says so once it has been read; otherwise, and when this
/// returns an error (a skipped array may hold an earlier one), [`parse_with_progress`]
/// says where the text is not JSON.
pub fn parse_deferring<'s>(src: &'s str, progress: &dyn Progress) -> Result<Tree<'s>, Error> {
    scan(src, progress, true)
}

fn scan<'s>(src: &'s str, progress: &dyn Progress, defer: bool) -> Result<Tree<'s>, Error> {
    let mut scanner = Scanner {
        defer,
        deferred: Vec::new(),
        s: src.as_bytes(),
        src,
        pass: Pass::new(src.as_bytes(), progress),
        i: 0,
        // Grown as needed: how many items there are depends on how much of the text is
        // array scalars (a few hundred items in the benchmark scene's 85 MB, one per 32
        // bytes in the shared corpus's median file).
        items: Vec::new(),
        stack: Vec::new(),
    };
    if scanner.s.starts_with(b"\xEF\xBB\xBF") {
        scanner.i = 3;
    }
    scanner.run()?;
    let checked = scanner
        .deferred
        .iter()
        .map(|_| AtomicBool::new(false))
        .collect();
    Ok(Tree {
        src,
        items: scanner.items,
        deferred: Deferred {
            arrays: scanner.deferred,
            checked,
            broken: AtomicBool::new(false),
        },
    })
}

struct Scanner<'s> {
    /// Skip arrays of plain numbers ([`parse_deferring`]).
    defer: bool,
    /// The arrays skipped.
    deferred: Vec<u32>,
    s: &'s [u8],
    src: &'s str,
    pass: Pass<'s>,
    i: usize,
    items: Vec<Item>,
    /// Open containers, innermost last.
    stack: Vec<u32>,
}

impl<'s> Scanner<'s> {
    fn run(&mut self) -> Result<(), Error> {
        let mut state = State::Value;
        loop {
            self.skip_ws();
            self.pass.reached(self.i);
            match state {
                State::Value => {
                    let Some(&b) = self.s.get(self.i) else {
                        return Err(self.eof_error());
                    };
                    // A scalar element of an array gets no item (see the module doc).
                    let keep = !self.count_in_parent(true);
                    state = match b {
                        b'{' => {
                            self.open(Kind::Object)?;
                            State::FirstKey
                        }
                        b'[' => {
                            self.open(Kind::Array)?;
                            self.skip_ws();
                            if self.s.get(self.i) == Some(&b']') {
                                self.i += 1;
                                self.close();
                            } else if let Some((end, commas)) =
                                self.defer.then(|| plain_array(self.s, self.i)).flatten()
                            {
                                let array = *self.stack.last().expect("the array just opened");
                                let item = &mut self.items[array as usize];
                                item.len = commas + 1;
                                item.flags = UNCHECKED;
                                self.deferred.push(array);
                                self.i = end + 1;
                                self.close();
                            } else {
                                // Stay expecting a value; an empty array was handled above.
                                continue;
                            }
                            State::AfterValue
                        }
                        b'"' => {
                            let (flags, start, end) = self.string()?;
                            if keep {
                                self.push(Kind::String, flags, start, end);
                            }
                            State::AfterValue
                        }
                        b'-' | b'0'..=b'9' => {
                            let (flags, start, end) = self.number()?;
                            if keep {
                                self.push(Kind::Number, flags, start, end);
                            }
                            State::AfterValue
                        }
                        b't' | b'f' | b'n' => {
                            let (kind, start, end) = self.literal()?;
                            if keep {
                                self.push(kind, 0, start, end);
                            }
                            State::AfterValue
                        }
                        _ => return Err(self.unexpected_value()),
                    };
                }
                State::FirstKey | State::Key => {
                    let Some(&b) = self.s.get(self.i) else {
                        return Err(self.eof_error());
                    };
                    match b {
                        b'}' if state == State::FirstKey => {
                            self.i += 1;
                            self.close();
                            state = State::AfterValue;
                        }
                        b'}' => {
                            return Err(self
                                .error_here("a trailing comma before `}` is not allowed in JSON"))
                        }
                        b'"' => {
                            self.count_in_parent(false);
                            let (flags, start, end) = self.string()?;
                            // Its `next` is set once its value is complete.
                            self.items.push(Item {
                                kind: Kind::Key,
                                flags,
                                start: start as u32,
                                end: end as u32,
                                next: 0,
                                len: 0,
                            });
                            self.skip_ws();
                            match self.s.get(self.i) {
                                Some(b':') => self.i += 1,
                                Some(_) => {
                                    return Err(self.error_here("expected `:` after the object key"))
                                }
                                None => return Err(self.eof_error()),
                            }
                            state = State::Value;
                        }
                        b'\'' => {
                            return Err(self.error_here(
                                "an object key must be in double quotes, not single quotes",
                            ))
                        }
                        _ => {
                            return Err(self.error_here(
                                "expected a string in double quotes as the object key",
                            ))
                        }
                    }
                }
                State::AfterValue => {
                    let Some(&top) = self.stack.last() else {
                        // The top-level value is complete: only whitespace may follow.
                        if self.i < self.s.len() {
                            return Err(
                                self.error_here("unexpected text after the end of the JSON value")
                            );
                        }
                        return Ok(());
                    };
                    let in_object = self.items[top as usize].kind == Kind::Object;
                    let Some(&b) = self.s.get(self.i) else {
                        return Err(self.eof_error());
                    };
                    match (b, in_object) {
                        (b',', true) => {
                            self.i += 1;
                            state = State::Key;
                        }
                        // The common case of big arrays: the numbers that follow, each
                        // with its comma, in one loop over local copies of the cursor and
                        // the count, without going round the state machine (and without
                        // an item).
                        (b',', false) => {
                            let s = self.s;
                            let mut i = self.i;
                            let mut numbers = 0;
                            let outcome = loop {
                                // A chunk at a time while it holds whole plain
                                // numbers, each with its comma.
                                while let Some(chunk) =
                                    s.get(i + 1..).and_then(|rest| rest.first_chunk::<CHUNK>())
                                {
                                    let (bytes, count) = plain_numbers(chunk);
                                    if count == 0 {
                                        break;
                                    }
                                    numbers += count;
                                    // At the last comma of those bytes.
                                    i += bytes as usize;
                                }
                                i = ws_end(s, i + 1);
                                match s.get(i) {
                                    Some(b']') => {
                                        self.i = i;
                                        break Err(self.error_here(
                                            "a trailing comma before `]` is not allowed in JSON",
                                        ));
                                    }
                                    Some(b'-' | b'0'..=b'9') => {
                                        numbers += 1;
                                        match simple_number(s, i) {
                                            Some((_, end)) => i = end,
                                            None => {
                                                self.i = i;
                                                if let Err(error) = self.number_full() {
                                                    break Err(error);
                                                }
                                                i = self.i;
                                            }
                                        }
                                        i = ws_end(s, i);
                                        if s.get(i) != Some(&b',') {
                                            break Ok(());
                                        }
                                    }
                                    _ => {
                                        state = State::Value;
                                        break Ok(());
                                    }
                                }
                            };
                            if outcome.is_ok() {
                                self.i = i;
                            }
                            self.items[top as usize].len += numbers;
                            outcome?;
                        }
                        (b'}', true) | (b']', false) => {
                            self.i += 1;
                            self.close();
                        }
                        (b'}' | b']', _) => {
                            let open = if in_object {
                                "an object (`{`)"
                            } else {
                                "an array (`[`)"
                            };
                            let at = self.items[top as usize].start as usize;
                            let (line, column) = line_column(self.src, at);
                            return Err(self.error_here(&format!(
                                "`{}` does not close {open} opened at line {line}, column {column}",
                                b as char
                            )));
                        }
                        (b'"', true) => {
                            return Err(
                                self.error_here("expected `,` or `}` between object members")
                            )
                        }
                        (_, true) => {
                            return Err(
                                self.error_here("expected `,` or `}` after the object member")
                            )
                        }
                        (_, false) => {
                            return Err(
                                self.error_here("expected `,` or `]` after the array element")
                            )
                        }
                    }
                }
            }
        }
    }

    #[inline(always)]
    fn skip_ws(&mut self) {
        while let Some(&b) = self.s.get(self.i) {
            if matches!(b, b' ' | b'\n' | b'\r' | b'\t') {
                self.i += 1;
            } else {
                break;
            }
        }
    }

    /// Counts one more element (`array`) or member (`!array`) in the innermost container
    /// when it is of that kind. A member is counted at its key, not again at its value.
    /// Returns whether the innermost container is an array.
    #[inline(always)]
    fn count_in_parent(&mut self, array: bool) -> bool {
        let Some(&top) = self.stack.last() else {
            return false;
        };
        let item = &mut self.items[top as usize];
        let in_array = item.kind == Kind::Array;
        if in_array == array {
            item.len += 1;
        }
        in_array
    }

    fn push(&mut self, kind: Kind, flags: u8, start: usize, end: usize) {
        let index = self.items.len() as u32;
        self.items.push(Item {
            kind,
            flags,
            start: start as u32,
            end: end as u32,
            next: index + 1,
            len: 0,
        });
        self.after_value_pushed(index);
    }

    /// Gives a member's key its `next` once its value is complete (leaf values: now;
    /// containers: when they close).
    fn after_value_pushed(&mut self, value: u32) {
        if let Some(k) = value.checked_sub(1) {
            let key = &mut self.items[k as usize];
            if key.kind == Kind::Key && key.next == 0 {
                let next = self.items[value as usize].next;
                self.items[k as usize].next = next;
            }
        }
    }

    fn open(&mut self, kind: Kind) -> Result<(), Error> {
        if self.stack.len() >= MAX_DEPTH {
            return Err(Error {
                at: self.i,
                len: 1,
                message: format!(
                    "nested too deeply: more than {MAX_DEPTH} levels of arrays and objects"
                ),
            });
        }
        let index = self.items.len() as u32;
        self.items.push(Item {
            kind,
            flags: 0,
            start: self.i as u32,
            end: 0,
            next: 0,
            len: 0,
        });
        self.stack.push(index);
        self.i += 1;
        Ok(())
    }

    fn close(&mut self) {
        let index = self.stack.pop().expect("close with an open container") as usize;
        let next = self.items.len() as u32;
        let item = &mut self.items[index];
        item.end = self.i as u32;
        item.next = next;
        self.after_value_pushed(index as u32);
    }

    /// A string or key starting at the `"` under the cursor: its flags and the span of its
    /// content.
    fn string(&mut self) -> Result<(u8, usize, usize), Error> {
        let open = self.i;
        let s = self.s;
        let mut i = open + 1;
        let mut flags = 0;
        loop {
            // Fast scan over plain bytes.
            while i < s.len() && !matches!(s[i], b'"' | b'\\' | 0..=0x1f) {
                i += 1;
            }
            let Some(&b) = s.get(i) else {
                return Err(Error {
                    at: open,
                    len: 1,
                    message: "unterminated string: no closing `\"`".to_string(),
                });
            };
            match b {
                b'"' => break,
                b'\\' => {
                    flags |= ESCAPED;
                    i = self.escape(i)?;
                }
                _ => {
                    let what = match b {
                        b'\n' => "a line break".to_string(),
                        b'\t' => "a tab".to_string(),
                        b'\r' => "a carriage return".to_string(),
                        _ => format!("the control character U+{b:04X}"),
                    };
                    let escape = match b {
                        b'\n' => "\\n".to_string(),
                        b'\t' => "\\t".to_string(),
                        b'\r' => "\\r".to_string(),
                        _ => format!("\\u{b:04x}"),
                    };
                    return Err(Error {
                        at: i,
                        len: 1,
                        message: format!("{what} inside a string: write it as `{escape}`"),
                    });
                }
            }
        }
        self.i = i + 1;
        Ok((flags, open + 1, i))
    }

    /// Checks the escape at the backslash `at`; returns the offset after it.
    fn escape(&self, at: usize) -> Result<usize, Error> {
        let s = self.s;
        match s.get(at + 1) {
            Some(b'"' | b'\\' | b'/' | b'b' | b'f' | b'n' | b'r' | b't') => Ok(at + 2),
            Some(b'u') => {
                let unit = self.hex4(at)?;
                if (0xDC00..0xE000).contains(&unit) {
                    return Err(Error {
                        at,
                        len: 6,
                        message: format!("`\\u{unit:04X}` is a lone low surrogate: it must follow a high surrogate (\\uD800–\\uDBFF)"),
                    });
                }
                if (0xD800..0xDC00).contains(&unit) {
                    let next = at + 6;
                    let low = if s.get(next) == Some(&b'\\') && s.get(next + 1) == Some(&b'u') {
                        Some(self.hex4(next)?)
                    } else {
                        None
                    };
                    return match low {
                        Some(low) if (0xDC00..0xE000).contains(&low) => Ok(next + 6),
                        _ => Err(Error {
                            at,
                            len: 6,
                            message: format!(
                                "`\\u{unit:04X}` is a lone high surrogate: it must be followed by a low surrogate (\\uDC00–\\uDFFF)"
                            ),
                        }),
                    };
                }
                Ok(at + 6)
            }
            Some(_) => {
                let ch = self.src[at + 1..].chars().next().unwrap_or('?');
                Err(Error {
                    at,
                    len: 1 + ch.len_utf8(),
                    message: format!(
                        "`\\{ch}` is not a JSON escape (use \\\" \\\\ \\/ \\b \\f \\n \\r \\t or \\uXXXX)"
                    ),
                })
            }
            None => Err(Error {
                at,
                len: 1,
                message: "unterminated string: no closing `\"`".to_string(),
            }),
        }
    }

    /// The four hex digits of the `\u` escape at the backslash `at`.
    fn hex4(&self, at: usize) -> Result<u32, Error> {
        let digits = self
            .s
            .get(at + 2..at + 6)
            .filter(|d| d.iter().all(u8::is_ascii_hexdigit));
        match digits {
            Some(d) => Ok(d.iter().fold(0, |acc, &b| {
                acc * 16 + (b as char).to_digit(16).unwrap_or(0)
            })),
            None => Err(Error {
                at,
                len: 2,
                message: "`\\u` must be followed by four hexadecimal digits".to_string(),
            }),
        }
    }

    /// A number starting at the cursor: `-?(0|[1-9][0-9]*)(\.[0-9]+)?([eE][+-]?[0-9]+)?`.
    ///
    /// Big arrays of numbers are most of a large scene, so the common shape
    /// `-?digits(.digits)?` is read here in one straight pass over its digits; anything
    /// else (exponents, errors) goes through the full grammar. Returns the flags and the
    /// span.
    #[inline(always)]
    fn number(&mut self) -> Result<(u8, usize, usize), Error> {
        let start = self.i;
        if let Some((flags, end)) = simple_number(self.s, start) {
            self.i = end;
            return Ok((flags, start, end));
        }
        self.number_full()
    }

    /// [`Scanner::number`] for exponents and errors: the grammar step by step.
    fn number_full(&mut self) -> Result<(u8, usize, usize), Error> {
        let s = self.s;
        let start = self.i;
        let mut i = start;
        let mut flags = 0;
        if s[i] == b'-' {
            i += 1;
        }
        let int_start = i;
        match s.get(i) {
            Some(b'0') => {
                i += 1;
                if s.get(i).is_some_and(u8::is_ascii_digit) {
                    return Err(self.bad_number(start, "a number may not have leading zeros"));
                }
            }
            Some(b'1'..=b'9') => {
                while s.get(i).is_some_and(u8::is_ascii_digit) {
                    i += 1;
                }
            }
            _ => {
                let message = if s[int_start..].starts_with(b"Infinity") {
                    "infinity is not a JSON number"
                } else {
                    "`-` must be followed by a digit"
                };
                return Err(self.bad_number(start, message));
            }
        }
        if s.get(i) == Some(&b'.') {
            i += 1;
            flags |= NOT_INTEGER;
            if !s.get(i).is_some_and(u8::is_ascii_digit) {
                return Err(self.bad_number(start, "a decimal point must be followed by a digit"));
            }
            while s.get(i).is_some_and(u8::is_ascii_digit) {
                i += 1;
            }
        }
        if matches!(s.get(i), Some(b'e' | b'E')) {
            i += 1;
            flags |= NOT_INTEGER;
            if matches!(s.get(i), Some(b'+' | b'-')) {
                i += 1;
            }
            if !s.get(i).is_some_and(u8::is_ascii_digit) {
                return Err(self.bad_number(start, "an exponent must have digits"));
            }
            while s.get(i).is_some_and(u8::is_ascii_digit) {
                i += 1;
            }
        }
        // A number glued to letters or more digits (`1.2.3`, `0x1F`, `1f`) is one bad token.
        if s.get(i)
            .is_some_and(|b| b.is_ascii_alphanumeric() || *b == b'.')
        {
            return Err(self.bad_number(start, "not a valid JSON number"));
        }
        self.i = i;
        Ok((flags, start, i))
    }

    #[cold]
    fn bad_number(&self, start: usize, why: &str) -> Error {
        let s = self.s;
        let mut end = start + 1;
        while end < s.len()
            && (s[end].is_ascii_alphanumeric() || matches!(s[end], b'.' | b'+' | b'-'))
        {
            end += 1;
        }
        Error {
            at: start,
            len: end - start,
            message: format!("`{}`: {why}", &self.src[start..end]),
        }
    }

    /// `true`, `false` or `null` at the cursor: its kind and span.
    fn literal(&mut self) -> Result<(Kind, usize, usize), Error> {
        let start = self.i;
        let (word, kind): (&[u8], _) = match self.s[start] {
            b't' => (b"true", Kind::True),
            b'f' => (b"false", Kind::False),
            _ => (b"null", Kind::Null),
        };
        let end = start + word.len();
        let glued = self.s.get(end).is_some_and(u8::is_ascii_alphanumeric);
        if self.s.get(start..end) != Some(word) || glued {
            return Err(self.unexpected_value());
        }
        self.i = end;
        Ok((kind, start, end))
    }

    #[cold]
    fn unexpected_value(&self) -> Error {
        let s = self.s;
        let start = self.i;
        let b = s[start];
        let word_end = {
            let mut e = start;
            while e < s.len() && (s[e].is_ascii_alphanumeric() || s[e] == b'_') {
                e += 1;
            }
            e
        };
        let word = &self.src[start..word_end];
        let message = match b {
            b']' | b'}' => {
                // After `[` or `,` (a trailing comma in an array is caught earlier).
                format!("expected a value, found `{}`", b as char)
            }
            b',' => "expected a value before `,`".to_string(),
            b'\'' => "strings must be in double quotes, not single quotes".to_string(),
            b'/' => "comments are not allowed in JSON".to_string(),
            b'+' => "a number may not start with `+`".to_string(),
            b'.' => "a number must have a digit before the decimal point".to_string(),
            _ if matches!(word, "NaN" | "Infinity" | "nan" | "inf" | "infinity") => {
                format!("`{word}` is not a JSON number")
            }
            _ if matches!(
                word,
                "True" | "TRUE" | "False" | "FALSE" | "Null" | "NULL" | "None"
            ) =>
            {
                format!(
                    "`{word}` is not a JSON literal: write `{}`",
                    word.to_ascii_lowercase().replace("none", "null")
                )
            }
            _ if !word.is_empty() => format!("expected a value, found `{word}`"),
            _ => {
                let ch = self.src[start..].chars().next().unwrap_or('?');
                format!("expected a value, found `{ch}`")
            }
        };
        let len = word_end.saturating_sub(start).max(1);
        Error {
            at: start,
            len,
            message,
        }
    }

    #[cold]
    fn error_here(&self, message: &str) -> Error {
        let len = self.src[self.i.min(self.src.len())..]
            .chars()
            .next()
            .map_or(0, char::len_utf8);
        Error {
            at: self.i,
            len,
            message: message.to_string(),
        }
    }

    #[cold]
    fn eof_error(&self) -> Error {
        let message = match self.stack.last() {
            None => "the input ends before a JSON value".to_string(),
            Some(&top) => {
                let item = &self.items[top as usize];
                let what = if item.kind == Kind::Object {
                    "an object (`{`)"
                } else {
                    "an array (`[`)"
                };
                let (line, column) = line_column(self.src, item.start as usize);
                format!("the input ends inside {what} opened at line {line}, column {column}")
            }
        };
        Error {
            at: self.s.len(),
            len: 0,
            message,
        }
    }
}

/// A number of the common shape `-?digits(.digits)?` at `start` (a `-` or a digit), whole
/// (not followed by an exponent, a letter or a dot): its flags and its end. None for
/// anything else, which [`Scanner::number_full`] reads or refuses.
#[inline(always)]
fn simple_number(s: &[u8], start: usize) -> Option<(u8, usize)> {
    let int_start = start + usize::from(s[start] == b'-');
    let int_end = digits_end(s, int_start);
    let mut end = int_end;
    let mut flags = 0;
    if s.get(end) == Some(&b'.') {
        end = digits_end(s, end + 1);
        flags = NOT_INTEGER;
    }
    let simple = int_end > int_start
        && (s[int_start] != b'0' || int_end - int_start == 1)
        // A decimal point needs a digit after it.
        && (flags == 0 || end > int_end + 1)
        && s.get(end)
            .is_none_or(|&b| NUMBER_CLASS[b as usize] & (EXP_SIGN | LETTER | DOT) == 0);
    simple.then_some((flags, end))
}

/// Bytes of the array text read at a time by [`plain_numbers`].
const CHUNK: usize = 16;

/// Bit masks of the bytes of a chunk (bit `k` for byte `k`) that are a comma, a `-`, a
/// decimal point, a `0` and any ASCII digit.
struct Classes {
    comma: u32,
    minus: u32,
    dot: u32,
    zero: u32,
    digit: u32,
}

/// [`Classes`] with SSE2, which every x86-64 processor has.
#[cfg(target_arch = "x86_64")]
#[inline(always)]
fn classes(chunk: &[u8; CHUNK]) -> Classes {
    use std::arch::x86_64::*;
    // SAFETY: SSE2 is part of x86-64; the load is unaligned and reads the 16 bytes of
    // `chunk`.
    unsafe {
        let v = _mm_loadu_si128(chunk.as_ptr().cast());
        let mask = |b: u8| _mm_movemask_epi8(_mm_cmpeq_epi8(v, _mm_set1_epi8(b as i8))) as u32;
        // A digit is a byte whose distance above `0` is at most 9 (unsigned).
        let d = _mm_sub_epi8(v, _mm_set1_epi8(b'0' as i8));
        let digit = _mm_movemask_epi8(_mm_cmpeq_epi8(_mm_min_epu8(d, _mm_set1_epi8(9)), d)) as u32;
        Classes {
            comma: mask(b','),
            minus: mask(b'-'),
            dot: mask(b'.'),
            zero: mask(b'0'),
            digit,
        }
    }
}

/// [`Classes`] a byte at a time.
#[cfg(not(target_arch = "x86_64"))]
#[inline(always)]
fn classes(chunk: &[u8; CHUNK]) -> Classes {
    let mask = |f: fn(u8) -> bool| (0..CHUNK).fold(0, |m, k| m | u32::from(f(chunk[k])) << k);
    Classes {
        comma: mask(|b| b == b','),
        minus: mask(|b| b == b'-'),
        dot: mask(|b| b == b'.'),
        zero: mask(|b| b == b'0'),
        digit: mask(|b| b.is_ascii_digit()),
    }
}

/// The plain numbers at the start of `chunk` (bytes of an array that start an element),
/// each followed by its comma: how many bytes they take (up to and including the chunk's
/// last comma) and how many numbers there are. (0, 0) unless every byte up to that comma
/// is part of a number of the shape `-?(0|[1-9][0-9]*)(\.[0-9]+)?` or its comma, so that
/// whatever the chunk holds (whitespace, exponents, strings, errors) is left to the
/// number-by-number reading, which alone reports errors. On bit masks of the chunk's
/// bytes, several numbers at once: most arrays of a large scene are plain numbers and
/// commas.
#[inline(always)]
fn plain_numbers(chunk: &[u8; CHUNK]) -> (u32, u32) {
    let Classes {
        comma,
        minus,
        dot,
        zero,
        digit,
    } = classes(chunk);
    if comma == 0 {
        return (0, 0);
    }
    // Bytes up to and including the last comma.
    let bytes = 32 - comma.leading_zeros();
    let prefix = u32::MAX >> (32 - bytes);
    // Where elements start: the first byte and those after a comma.
    let start = (comma << 1 | 1) & prefix;
    // Where the digits before the decimal point start: after a leading `-`.
    let int_start = (start & !minus) | minus << 1;
    // Bytes at or after a decimal point in its element (a prefix sum within elements).
    let mut go = !comma;
    let mut fraction = dot;
    fraction |= fraction << 1 & go;
    go &= go << 1;
    fraction |= fraction << 2 & go;
    go &= go << 2;
    fraction |= fraction << 4 & go;
    go &= go << 4;
    fraction |= fraction << 8 & go;
    let bad = !(digit | comma | minus | dot)
        // An empty element (`,,`).
        | (start & comma)
        // `-` only first, and before a digit.
        | (minus & !start)
        | (minus << 1 & !digit)
        // No leading zeros.
        | ((int_start & zero) << 1 & digit)
        // A digit on each side of the decimal point, one point per number.
        | (dot & !(digit << 1))
        | (dot << 1 & !digit)
        | (dot & fraction << 1);
    if bad & prefix != 0 {
        return (0, 0);
    }
    (bytes, comma.count_ones())
}

/// The array text starting at `s[i]` (after its `[`) when it is digits, `-`, `.` and
/// commas only up to its `]`: the offset of the `]` and how many commas there are. A
/// chunk at a time ([`classes`]) while whole chunks are such bytes.
#[inline(always)]
fn plain_array(s: &[u8], mut i: usize) -> Option<(usize, u32)> {
    let mut commas = 0;
    while let Some(chunk) = s.get(i..).and_then(|rest| rest.first_chunk::<CHUNK>()) {
        let Classes {
            comma,
            minus,
            dot,
            digit,
            ..
        } = classes(chunk);
        let plain = comma | minus | dot | digit;
        if plain != (1 << CHUNK) - 1 {
            let k = plain.trailing_ones() as usize;
            commas += (comma & ((1 << k) - 1)).count_ones();
            i += k;
            break;
        }
        commas += comma.count_ones();
        i += CHUNK;
    }
    loop {
        match s.get(i)? {
            b',' => commas += 1,
            b'-' | b'.' | b'0'..=b'9' => {}
            b']' => return Some((i, commas)),
            _ => return None,
        }
        i += 1;
    }
}

/// The end of the run of JSON whitespace starting at `i`.
#[inline(always)]
fn ws_end(s: &[u8], mut i: usize) -> usize {
    while let Some(b' ' | b'\n' | b'\r' | b'\t') = s.get(i) {
        i += 1;
    }
    i
}

/// The end of the run of ASCII digits starting at `i`, eight bytes at a time while eight
/// remain.
#[inline(always)]
fn digits_end(s: &[u8], mut i: usize) -> usize {
    while let Some(&chunk) = s.get(i..).and_then(|rest| rest.first_chunk::<8>()) {
        let k = leading_digits(u64::from_le_bytes(chunk));
        i += k as usize;
        if k < 8 {
            return i;
        }
    }
    while s.get(i).is_some_and(u8::is_ascii_digit) {
        i += 1;
    }
    i
}

/// 1-based line and column (in characters) of a byte offset, for messages.
fn line_column(src: &str, at: usize) -> (usize, usize) {
    let before = &src.as_bytes()[..at.min(src.len())];
    let line = before.iter().filter(|&&b| b == b'\n').count() + 1;
    let line_start = before
        .iter()
        .rposition(|&b| b == b'\n')
        .map_or(0, |p| p + 1);
    let column = src[line_start..at.min(src.len())].chars().count() + 1;
    (line, column)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn kinds(t: &Tree) -> Vec<Kind> {
        t.items.iter().map(|i| i.kind).collect()
    }

    fn err(src: &str) -> Error {
        match parse(src) {
            Ok(_) => panic!("`{src}` parsed"),
            Err(e) => e,
        }
    }

    #[test]
    fn spans_of_keys_and_values() {
        let src = r#"{ "a": [1, -2.5e3, true], "b": {"c": null}, "s": "x\ny" }"#;
        let t = parse(src).unwrap();
        // The array's scalars have no items.
        assert_eq!(
            kinds(&t),
            vec![
                Kind::Object,
                Kind::Key,
                Kind::Array,
                Kind::Key,
                Kind::Object,
                Kind::Key,
                Kind::Null,
                Kind::Key,
                Kind::String,
            ]
        );
        assert_eq!(t.item(0).len, 3);
        assert_eq!(t.item(2).len, 3);
        assert_eq!(t.full_span(0), (0, src.len()));
        let members: Vec<_> = t
            .members(0)
            .map(|(k, v)| (t.str(k).into_owned(), v))
            .collect();
        assert_eq!(
            members,
            vec![("a".into(), 2), ("b".into(), 4), ("s".into(), 8)]
        );
        assert_eq!(t.raw(1), "a");
        assert_eq!(&src[t.full_span(1).0..t.full_span(1).1], "\"a\"");
        assert_eq!(t.raw(2), "[1, -2.5e3, true]");
        let elements: Vec<ValueRef> = t.elements(2).collect();
        let texts: Vec<(Kind, &str)> = elements.iter().map(|&e| (t.kind(e), t.raw(e))).collect();
        assert_eq!(
            texts,
            [
                (Kind::Number, "1"),
                (Kind::Number, "-2.5e3"),
                (Kind::True, "true")
            ]
        );
        assert_eq!(t.full_span(elements[1]), (11, 17));
        assert_eq!(t.item(elements[1]).flags & NOT_INTEGER, NOT_INTEGER);
        assert_eq!(t.item(elements[0]).flags & NOT_INTEGER, 0);
        assert_eq!(t.raw(4), r#"{"c": null}"#);
        assert_eq!(t.next(1), 3, "a key's next skips its value");
        assert_eq!(t.next(4), 7);
        assert_eq!(t.str(8), "x\ny");
        assert!(matches!(t.str(1), Cow::Borrowed(_)));
    }

    #[test]
    fn elements_mix_scalars_read_back_and_containers() {
        let src = "[ 0 ,-1.5E+2,\t\"q\\\"\" , [7], {\"k\": [false, null]}, \"\", 12 ]";
        let t = parse(src).unwrap();
        assert_eq!(t.item(0).len, 7);
        let elements: Vec<ValueRef> = t.elements(0).collect();
        assert_eq!(t.elements(0).len(), 7);
        let found: Vec<(Kind, &str)> = elements
            .iter()
            .map(|&e| (t.kind(e), &src[t.full_span(e).0..t.full_span(e).1]))
            .collect();
        assert_eq!(
            found,
            [
                (Kind::Number, "0"),
                (Kind::Number, "-1.5E+2"),
                (Kind::String, "\"q\\\"\""),
                (Kind::Array, "[7]"),
                (Kind::Object, "{\"k\": [false, null]}"),
                (Kind::String, "\"\""),
                (Kind::Number, "12"),
            ]
        );
        assert_eq!(t.str(elements[2]), "q\"");
        assert_eq!(t.object(elements[4]), Some(2));
        assert_eq!(t.object(elements[3]), None);
        assert_eq!(t.object(elements[0]), None);
        let ValueRef::Item(inner) = elements[3] else {
            panic!("a nested array is an item")
        };
        assert_eq!(t.raw(t.elements(inner).next().unwrap()), "7");
        let (_, k) = t.get(2, "k").unwrap();
        let literals: Vec<Kind> = t.elements(k).map(|e| t.kind(e)).collect();
        assert_eq!(literals, [Kind::False, Kind::Null]);
        // Only the containers and the object's key are items.
        assert_eq!(
            kinds(&t),
            [
                Kind::Array,
                Kind::Array,
                Kind::Object,
                Kind::Key,
                Kind::Array
            ]
        );
    }

    /// Arrays of every kind of element with varied whitespace: each element read back
    /// has the kind and span it was written with.
    #[test]
    fn elements_are_read_back_with_their_spans() {
        let tokens: [(&str, Kind); 12] = [
            ("0", Kind::Number),
            ("-12.5e-3", Kind::Number),
            ("3E+7", Kind::Number),
            ("42", Kind::Number),
            ("\"\"", Kind::String),
            ("\"a\\\"],\\\\\"", Kind::String),
            ("\"é\\u00e9\"", Kind::String),
            ("true", Kind::True),
            ("false", Kind::False),
            ("null", Kind::Null),
            ("[1, [\"]\"], {}]", Kind::Array),
            ("{\"k\": [2, 3], \"s\": \"]\"}", Kind::Object),
        ];
        let spaces = ["", " ", "\n", "\t ", "\r\n  "];
        let mut state = 0x2545_F491_4F6C_DD1Du64;
        let mut next = |n: usize| {
            state ^= state << 13;
            state ^= state >> 7;
            state ^= state << 17;
            (state % n as u64) as usize
        };
        for _ in 0..300 {
            let count = next(9);
            let mut src = String::from("[");
            let mut expected = Vec::new();
            for k in 0..count {
                if k > 0 {
                    src.push_str(spaces[next(spaces.len())]);
                    src.push(',');
                }
                src.push_str(spaces[next(spaces.len())]);
                let (token, kind) = tokens[next(tokens.len())];
                expected.push((kind, (src.len(), src.len() + token.len())));
                src.push_str(token);
            }
            src.push_str(spaces[next(spaces.len())]);
            src.push(']');
            let t = parse(&src).unwrap();
            let found: Vec<(Kind, (usize, usize))> =
                t.elements(0).map(|e| (t.kind(e), t.full_span(e))).collect();
            assert_eq!(found, expected, "{src}");
            assert_eq!(t.item(0).len as usize, count);
        }
    }

    #[test]
    fn escapes_are_unescaped() {
        let t = parse(r#"["a\"b\\c\/d\b\f\n\r\t", "\u00e9\ud83d\ude00", "plain é"]"#).unwrap();
        let e: Vec<ValueRef> = t.elements(0).collect();
        assert_eq!(t.str(e[0]), "a\"b\\c/d\u{8}\u{c}\n\r\t");
        assert_eq!(t.str(e[1]), "é😀");
        assert_eq!(t.str(e[2]), "plain é");
        assert!(t.item(e[1]).flags & ESCAPED != 0);
        assert!(t.item(e[2]).flags & ESCAPED == 0);
    }

    #[test]
    fn duplicate_keys_are_kept() {
        let t = parse(r#"{"a": 1, "a": 2}"#).unwrap();
        let values: Vec<_> = t.members(0).map(|(_, v)| t.raw(v)).collect();
        assert_eq!(values, vec!["1", "2"]);
        assert_eq!(t.item(0).len, 2);
    }

    #[test]
    fn empty_containers_and_nesting() {
        let t = parse(r#"{"a": [], "b": {}, "c": [[], [{}]]}"#).unwrap();
        assert_eq!(t.item(0).len, 3);
        let (_, c) = t.get(0, "c").unwrap();
        assert_eq!(t.item(c).len, 2);
        let inner: Vec<_> = t.elements(c).map(|e| t.item(e).len).collect();
        assert_eq!(inner, vec![0, 1]);
        assert_eq!(t.next(0), t.items.len());
        let (_, a) = t.get(0, "a").unwrap();
        assert_eq!(t.item(a).len, 0);
        assert_eq!(t.elements(a).count(), 0);
    }

    #[test]
    fn scalars_at_the_top() {
        for (src, kind) in [
            ("1", Kind::Number),
            ("\"x\"", Kind::String),
            (" null ", Kind::Null),
            ("[]", Kind::Array),
        ] {
            assert_eq!(parse(src).unwrap().kind(0), kind);
        }
        assert_eq!(parse("\u{feff}{}").unwrap().span(0), (3, 5));
    }

    #[test]
    fn errors_have_positions() {
        let cases: &[(&str, usize, &str)] = &[
            ("", 0, "ends before a JSON value"),
            ("{\"a\": 1,}", 8, "trailing comma before `}`"),
            ("[1, 2,]", 6, "trailing comma before `]`"),
            ("{\"a\" 1}", 5, "expected `:`"),
            ("{\"a\": 1 \"b\": 2}", 8, "expected `,` or `}` between"),
            ("[1 2]", 3, "expected `,` or `]`"),
            ("{'a': 1}", 1, "double quotes"),
            ("[01]", 1, "leading zeros"),
            ("[1.]", 1, "decimal point"),
            ("[.5]", 1, "digit before the decimal point"),
            ("[+1]", 1, "`+`"),
            ("[1e]", 1, "exponent"),
            ("[NaN]", 1, "not a JSON number"),
            ("[-Infinity]", 1, "infinity"),
            ("[True]", 1, "write `true`"),
            ("[tru]", 1, "expected a value"),
            ("[\"a\nb\"]", 3, "line break"),
            ("[\"a\\qb\"]", 3, "not a JSON escape"),
            ("[\"\\ud800\"]", 2, "lone high surrogate"),
            ("[\"\\udc00\"]", 2, "lone low surrogate"),
            ("[\"\\u12\"]", 2, "four hexadecimal"),
            ("[\"abc", 1, "unterminated string"),
            ("{\"a\": [1, 2}", 11, "does not close an array"),
            (
                "{\"a\": 1",
                7,
                "ends inside an object (`{`) opened at line 1, column 1",
            ),
            ("{} x", 3, "after the end"),
            ("{} {}", 3, "after the end"),
            ("[1, // c\n 2]", 4, "comments"),
            ("{,}", 1, "object key"),
            ("[,1]", 1, "before `,`"),
            // Inside arrays of numbers, which keep no items: the same checks.
            ("[1, 2, 3 4]", 9, "expected `,` or `]`"),
            ("[1,, 2]", 3, "before `,`"),
            ("[1, 2.]", 4, "decimal point"),
            ("[1, 2, 03]", 7, "leading zeros"),
            ("[0, -]", 4, "`-` must be followed"),
            ("[0, 1e+]", 4, "exponent"),
            ("[0, 1x]", 4, "not a valid JSON number"),
            ("[1, 2}", 5, "does not close an array"),
            ("[1, tru]", 4, "expected a value"),
            ("[1, \"a]", 4, "unterminated string"),
            ("[1, 2", 5, "ends inside an array"),
            ("[1.2.3]", 1, "not a valid JSON number"),
            ("[-01]", 1, "leading zeros"),
            ("[1.e3]", 1, "decimal point"),
            ("[--1]", 1, "`-` must be followed"),
            ("[0x1F]", 1, "not a valid JSON number"),
            ("[1.5f]", 1, "not a valid JSON number"),
            ("[2.5E]", 1, "exponent"),
            ("{\"a\": 0.}", 6, "decimal point"),
            ("-", 0, "`-` must be followed"),
            // Arrays without whitespace, read sixteen bytes at a time where they can be.
            ("[0,1,2,3,4,5,6,7,8,9,01,2]", 21, "leading zeros"),
            (
                "[0,1,2,3,-0.5,6.25,1.2.3,4,5]",
                19,
                "not a valid JSON number",
            ),
            ("[0,1,2,3,4,5,6,,7,8,9,1,2]", 15, "before `,`"),
            ("[0,1,2,3,4,5,6,7.,8,9,1,2]", 15, "decimal point"),
            ("[0,1,2,3,4,5,6,-.5,8,9,1,2]", 15, "`-` must be followed"),
            ("[0,1,2,3,4,5,6,7,8,9,10,11,]", 27, "trailing comma"),
            ("[0,1,2,3,4,5,6,7,8,9,10,11}", 26, "does not close an array"),
            ("[0,1,2,3,4,5,6,7,8,-9-1,1]", 21, "expected `,` or `]`"),
        ];
        for &(src, at, needle) in cases {
            let e = err(src);
            assert_eq!(e.at, at, "position for {src:?}: {e:?}");
            assert!(
                e.message.contains(needle),
                "message for {src:?}: {:?}",
                e.message
            );
        }
    }

    #[test]
    fn digit_runs_end_where_a_byte_at_a_time_says() {
        // Every byte value after runs of every length around the eight-byte steps, with
        // digits after it that must not count.
        for len in 0..20 {
            for stop in 0..=255u8 {
                let mut s = vec![b'7'; len];
                s.push(stop);
                s.extend_from_slice(b"0123456789");
                for from in 0..=len {
                    let slow = from
                        + s[from..]
                            .iter()
                            .position(|b| !b.is_ascii_digit())
                            .unwrap_or(s.len() - from);
                    assert_eq!(digits_end(&s, from), slow, "{len} digits, then {stop}");
                }
            }
        }
    }

    /// The chunk check against the grammar read byte by byte, over chunks of the bytes
    /// that matter to its rules.
    #[test]
    fn plain_numbers_agree_with_the_grammar() {
        fn plain(element: &[u8]) -> bool {
            let digits = element.strip_prefix(b"-").unwrap_or(element);
            let (int, fraction) = match digits.iter().position(|&b| b == b'.') {
                Some(p) => (&digits[..p], Some(&digits[p + 1..])),
                None => (digits, None),
            };
            let all_digits = |d: &[u8]| !d.is_empty() && d.iter().all(u8::is_ascii_digit);
            all_digits(int) && (int[0] != b'0' || int.len() == 1) && fraction.is_none_or(all_digits)
        }
        fn expected(chunk: &[u8; CHUNK]) -> (u32, u32) {
            let Some(last) = chunk.iter().rposition(|&b| b == b',') else {
                return (0, 0);
            };
            let elements: Vec<&[u8]> = chunk[..last].split(|&b| b == b',').collect();
            if elements.iter().all(|e| plain(e)) {
                (last as u32 + 1, elements.len() as u32)
            } else {
                (0, 0)
            }
        }
        // Mostly what plain numbers are made of, sometimes anything else that can be in
        // an array.
        let common = b"00123456789,,,,--..";
        let rare = b"eE+ \n\"]}x\xc3\x80\xff";
        let mut state = 0x9E37_79B9_7F4A_7C15u64;
        let mut next = || {
            state ^= state << 13;
            state ^= state >> 7;
            state ^= state << 17;
            state
        };
        let mut accepted = 0;
        for _ in 0..400_000 {
            let mut chunk = [0u8; CHUNK];
            for b in &mut chunk {
                let r = next();
                let pool: &[u8] = if r % 32 == 0 { rare } else { common };
                *b = pool[((r >> 8) % pool.len() as u64) as usize];
            }
            let want = expected(&chunk);
            accepted += usize::from(want.1 > 0);
            assert_eq!(
                plain_numbers(&chunk),
                want,
                "{:?}",
                String::from_utf8_lossy(&chunk)
            );
        }
        assert!(accepted > 10_000, "{accepted}");
        for (chunk, want) in [
            (b"0,1,2,3,-10.945,", (16, 5)),
            (b"-0.5,0,1,2,3,4,5", (15, 6)),
            (b"1,2,3,1.2.3,4,5,", (0, 0)),
            (b"1,2,3,01,2,3,4,5", (0, 0)),
            (b"-01,2,3,4,5,6,7,", (0, 0)),
            (b"1,2,3,4,5,6,,2,3", (0, 0)),
            (b"1,2,3,4,5,6,7.,3", (0, 0)),
            (b"1234567812345678", (0, 0)),
            (b"1,2,3,4,5,6,1e3,", (0, 0)),
            (b"1,2,3,4,5,6,7,8-", (14, 7)),
        ] {
            assert_eq!(plain_numbers(chunk), want);
        }
    }

    #[test]
    fn numbers_of_every_shape() {
        for (number, integer) in [
            ("0", true),
            ("-0", true),
            ("7", true),
            ("-1234567890123", true),
            ("0.5", false),
            ("-0.25", false),
            ("10.000", false),
            ("1e3", false),
            ("-1.25E-3", false),
            ("0e+0", false),
        ] {
            for src in [number.to_string(), format!("{{\"a\": {number}}}")] {
                let t = parse(&src).unwrap();
                let value = if t.kind(0) == Kind::Object { 2 } else { 0 };
                assert_eq!(t.kind(value), Kind::Number, "{src}");
                assert_eq!(t.raw(value), number, "{src}");
                assert_eq!(t.item(value).flags & NOT_INTEGER == 0, integer, "{src}");
            }
            let src = format!("[{number},{number} ]");
            let t = parse(&src).unwrap();
            for e in t.elements(0) {
                assert_eq!(t.raw(e), number, "{src}");
                assert_eq!(t.item(e).flags & NOT_INTEGER == 0, integer, "{src}");
            }
        }
    }

    #[test]
    fn depth_is_capped_without_recursion() {
        let deep = "[".repeat(MAX_DEPTH) + &"]".repeat(MAX_DEPTH);
        assert!(parse(&deep).is_ok());
        let too_deep = "[".repeat(MAX_DEPTH + 1) + &"]".repeat(MAX_DEPTH + 1);
        let e = err(&too_deep);
        assert_eq!(e.at, MAX_DEPTH);
        assert!(e.message.contains("nested too deeply"));
        // Far deeper input fails fast at the same place, without overflowing the stack.
        let e = err(&"{\"a\":".repeat(1_000_000));
        assert!(e.message.contains("nested too deeply"));
    }

    #[test]
    fn truncated_inputs_never_panic() {
        let src = r#"{"X3D": {"@v": "4.0", "a": [1, -2.5e-3, true, false, null, "s\u00e9\"", {"b": []}]}}"#;
        for cut in 0..src.len() {
            if src.is_char_boundary(cut) {
                let _ = parse(&src[..cut]);
            }
        }
        assert!(parse(src).is_ok());
    }
}
