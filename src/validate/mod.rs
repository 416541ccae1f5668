//! The rules of `RULES.md`, one per file, grouped by component. [`check`] runs those the
//! configuration enables on a parsed document; rules found while reading are reported by
//! the readers and the model builder and only filtered here.

pub mod document;
mod edits;
pub mod environmental_effects;
pub mod events;
pub mod geometry2d;
pub mod geometry3d;
pub mod geospatial;
pub mod grouping;
pub mod hanim;
mod instances;
pub mod interpolation;
pub mod layering;
pub mod layout;
pub mod lighting;
pub mod navigation;
pub mod networking;
pub mod numbers;
pub mod nurbs;
pub mod particles;
pub mod picking;
pub mod prototypes;
mod registry;
pub mod rendering;
pub mod rigid_body;
pub mod scripting;
pub mod sensors;
pub mod shaders;
pub mod shape;
pub mod sound;
pub mod suggest;
pub mod terms;
pub mod text;
pub mod texture_projection;
pub mod texturing;

pub use registry::{find_rule, CHECKS, RULES};

use crate::config::CheckConfig;
use crate::limits::MAX_DIAGNOSTICS;
use crate::model::rules::LIMIT_EXCEEDED;
use std::collections::HashMap;

use crate::diagnostic::{Diagnostic, Level, Rule};
use crate::model::{Document, FieldEntry, NodeId, Span, Value};
use crate::schema::Version;

/// A rule of the registry with its check function; `run` is None for the rules the
/// readers and the model builder report while reading (they are only filtered here).
pub struct Check {
    pub rule: &'static Rule,
    pub run: Option<fn(&mut Ctx)>,
}

impl Check {
    /// A rule reported while reading, listed in its group for the catalogue order.
    pub const fn reported(rule: &'static Rule) -> Check {
        Check { rule, run: None }
    }
}

/// What a rule's check sees: the document and its source, its version and where to report.
pub struct Ctx<'a> {
    pub doc: &'a Document,
    pub source: &'a [u8],
    /// Told how far a rule that reads the whole of `source` has got (see
    /// [`crate::parse::behind`]); the rules otherwise read it only at spans.
    pub progress: &'a dyn crate::parse::Progress,
    /// The version whose rules apply (the document's, or the latest when it names none).
    pub version: Version,
    pub config: &'a CheckConfig,
    /// The checked file, as named; None for standard input.
    pub file: Option<&'a std::path::Path>,
    /// The directory of the checked file, against which relative URLs resolve; None for
    /// standard input.
    pub base: Option<&'a std::path::Path>,
    /// What each ExternProtoDeclare's url resolves to (deep level; empty below it).
    pub externs: prototypes::externs::Externs,
    /// The shader analysis, made by the first rule that needs it ([`shaders::analysis`]).
    shaders: Option<std::rc::Rc<shaders::analysis::Analysis>>,
    /// What each Inline's url resolves to (deep level; empty below it).
    pub inlines: networking::inlines::Inlines,
    /// What each IMPORT statement imports (deep level; empty below it).
    pub imports: networking::imports::Imports,
    /// The code of each Script, read and parsed when a rule first asks ([`Ctx::scripts`]).
    scripts: std::cell::OnceCell<scripting::Scripts>,
    /// The faces of the polygonal geometries as the deep rules judge them, walked when a
    /// rule first asks ([`Ctx::face_survey`]).
    face_survey: std::cell::OnceCell<std::rc::Rc<FaceSurveys<'a>>>,
    diagnostics: Vec<Diagnostic>,
    /// Folded findings: (code, node, field) → index in `diagnostics`.
    folded: HashMap<(&'static str, NodeId, String), usize>,
    /// Whether [`MAX_DIAGNOSTICS`] was reached (and reported).
    full: bool,
}

/// Each judged polygonal geometry with what [`rendering::face_survey`] found in it.
type FaceSurveys<'a> = Vec<(
    rendering::geometry::Checked<'a>,
    rendering::face_survey::Survey,
)>;

impl<'a> Ctx<'a> {
    /// The faces of the polygonal geometries, walked once for the deep rules that judge
    /// them (DEGENERATE_TRIANGLE, NORMALS_CONTRADICT_CCW, FACE_SELF_INTERSECTING), on
    /// first use.
    pub fn face_survey(&self) -> std::rc::Rc<FaceSurveys<'a>> {
        let wanted = rendering::face_survey::Wanted {
            degenerate: self
                .config
                .runs(&rendering::degenerate_triangle::DEGENERATE_TRIANGLE),
            normals: self
                .config
                .runs(&rendering::normals_contradict_ccw::NORMALS_CONTRADICT_CCW),
            crossing: self
                .config
                .runs(&rendering::face_self_intersecting::FACE_SELF_INTERSECTING),
        };
        self.face_survey
            .get_or_init(|| std::rc::Rc::new(rendering::face_survey::survey(self.doc, wanted)))
            .clone()
    }
}

/// How many element indices a folded diagnostic lists.
pub const FOLDED_INDICES: usize = 10;

impl Ctx<'_> {
    /// The Scripts' code, read and parsed on first use (never for a document whose rules
    /// do not ask, and at no cost beyond a look at each node for one without Scripts).
    pub fn scripts(&self) -> &scripting::Scripts {
        self.scripts.get_or_init(|| scripting::Scripts::read(self))
    }

    pub fn report(&mut self, diagnostic: Diagnostic) {
        if self.has_room() {
            self.diagnostics.push(diagnostic);
        }
    }

    /// Whether findings are no longer kept, so that a rule that may report one per node
    /// can stop before it spends time on what would be dropped.
    pub fn is_full(&mut self) -> bool {
        !self.has_room()
    }

    /// Whether another finding may be kept: past [`MAX_DIAGNOSTICS`] they are dropped, and
    /// that is reported once.
    fn has_room(&mut self) -> bool {
        if self.diagnostics.len() < MAX_DIAGNOSTICS {
            return true;
        }
        if !self.full {
            self.full = true;
            self.diagnostics.push(Diagnostic::new(
                &LIMIT_EXCEEDED,
                self.doc.root_span,
                format!("more than {MAX_DIAGNOSTICS} findings in this document; the rest are not reported"),
            ));
        }
        false
    }

    /// Reports a finding that can repeat along one field (a bad index, a short polygon).
    /// With folding on (the default; `--no-fold` turns it off) the repeats of one code on
    /// one node's field become the first diagnostic with a count and the first indices,
    /// and `make` runs only for that first one, so a million bad indices cost a counter.
    pub fn report_repeated(
        &mut self,
        rule: &'static Rule,
        node: NodeId,
        field: &str,
        index: usize,
        make: impl FnOnce() -> Diagnostic,
    ) {
        if !self.config.fold {
            if self.has_room() {
                self.diagnostics.push(make().index(index));
            }
            return;
        }
        let key = (rule.code, node, field.to_string());
        if let Some(&at) = self.folded.get(&key) {
            let folded = &mut self.diagnostics[at];
            folded.count += 1;
            if folded.indices.len() < FOLDED_INDICES {
                folded.indices.push(index);
            }
            return;
        }
        if !self.has_room() {
            return;
        }
        let mut diagnostic = make().index(index);
        diagnostic.indices.push(index);
        self.folded.insert(key, self.diagnostics.len());
        self.diagnostics.push(diagnostic);
    }

    /// Says in each folded diagnostic's message how many it stands for.
    fn finish(mut self) -> Vec<Diagnostic> {
        for &at in self.folded.values() {
            let d = &mut self.diagnostics[at];
            if d.count > 1 {
                let shown: Vec<String> = d.indices.iter().map(usize::to_string).collect();
                let more = if d.count > d.indices.len() {
                    ", …"
                } else {
                    ""
                };
                d.message = format!(
                    "{} ({} in all, at indices {}{more})",
                    d.message,
                    d.count,
                    shown.join(", ")
                );
            }
        }
        instances::fold(self.doc, self.diagnostics)
    }
    /// The place of the `k`-th number of a field's value and its text as written; for a
    /// value passed in through IS, the place of the IS/connect and the number as read.
    pub fn scalar_text(&self, entry: &FieldEntry, k: usize) -> (Span, String) {
        let span = self.scalar_span(entry, k);
        if entry.origin == crate::model::Origin::Is {
            let text = match &entry.value {
                Value::Floats(v) => v.get(k).map(f32::to_string),
                Value::Doubles(v) => v.get(k).map(f64::to_string),
                Value::Int32s(v) => v.get(k).map(i32::to_string),
                Value::Bools(v) => v
                    .get(k)
                    .map(|b| if *b { "true" } else { "false" }.to_string()),
                _ => None,
            };
            return (span, text.unwrap_or_default());
        }
        let text = self.source.get(span.range()).unwrap_or_default();
        (span, String::from_utf8_lossy(text).into_owned())
    }

    /// The place of the `k`-th number of a field's value (XML attribute text or JSON array),
    /// or the whole value when it cannot be told.
    pub fn scalar_span(&self, entry: &FieldEntry, k: usize) -> Span {
        // A value passed in through IS is placed at the IS/connect, which holds no numbers.
        if entry.origin == crate::model::Origin::Is {
            return entry.span;
        }
        let range = entry.span.range();
        let Some(text) = self.source.get(range.clone()) else {
            return entry.span;
        };
        let is_separator = |b: u8| b.is_ascii_whitespace() || matches!(b, b',' | b'[' | b']');
        let (mut at, mut seen) = (0, 0);
        while at < text.len() {
            if is_separator(text[at]) {
                at += 1;
                continue;
            }
            if text[at] == b'#' {
                at = comment_end(text, at);
                continue;
            }
            let start = at;
            while at < text.len() && !is_separator(text[at]) && text[at] != b'#' {
                at += 1;
            }
            if seen == k {
                return Span::new(range.start + start, range.start + at);
            }
            seen += 1;
        }
        entry.span
    }
}

/// The end of the comment starting at `at` (a `#`) in the text of a field's value: a
/// block comment `#/* … */#` (19776-2 A.1.2) or the rest of the line. Only ClassicVRML
/// and VRML97 values hold comments; in XML and JSON a `#` among numbers fails to parse,
/// so no rule asks for the place of a number there.
pub fn comment_end(text: &[u8], at: usize) -> usize {
    if text[at + 1..].starts_with(b"/*") {
        if let Some(k) = memchr::memmem::find(&text[at + 3..], b"*/#") {
            return at + 3 + k + 3;
        }
    }
    memchr::memchr2(b'\n', b'\r', &text[at..]).map_or(text.len(), |k| at + k)
}

/// Runs every enabled rule with a check on `doc`, read from `file` (None: standard input).
pub fn check(
    doc: &Document,
    source: &[u8],
    file: Option<&std::path::Path>,
    config: &CheckConfig,
) -> Vec<Diagnostic> {
    let externs = if config.level >= Level::Deep {
        prototypes::externs::Externs::resolve(doc, file, config)
    } else {
        Default::default()
    };
    check_with(doc, source, &(), file, config, externs)
}

/// [`check`] with the document's ExternProtoDeclares already resolved (deep level; empty
/// below it), telling `progress` how far a rule that reads the whole source has got.
pub fn check_with(
    doc: &Document,
    source: &[u8],
    progress: &dyn crate::parse::Progress,
    file: Option<&std::path::Path>,
    config: &CheckConfig,
    externs: prototypes::externs::Externs,
) -> Vec<Diagnostic> {
    let base = file.map(|file| match file.parent() {
        Some(dir) if !dir.as_os_str().is_empty() => dir,
        _ => std::path::Path::new("."),
    });
    let (inlines, imports) = if config.level >= Level::Deep {
        let inlines = networking::inlines::Inlines::resolve(doc, file, config);
        let imports = networking::imports::Imports::resolve(doc, &inlines);
        (inlines, imports)
    } else {
        Default::default()
    };
    let mut ctx = Ctx {
        doc,
        source,
        progress,
        version: doc.schema_version(),
        config,
        file,
        base,
        externs,
        shaders: None,
        inlines,
        imports,
        scripts: std::cell::OnceCell::new(),
        face_survey: std::cell::OnceCell::new(),
        diagnostics: Vec::new(),
        folded: HashMap::new(),
        full: false,
    };
    for check in CHECKS.iter() {
        if let Some(run) = check.run {
            if config.runs(check.rule) {
                run(&mut ctx);
            }
        }
    }
    ctx.finish()
}
