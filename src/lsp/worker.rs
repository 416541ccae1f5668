//! The checking thread: checks documents off the main loop (so requests are answered while
//! a large scene is checked), coalescing edits — changes that arrive while a check runs
//! are taken together, and only the newest text of each document is checked — and
//! publishes each result.

use std::collections::HashMap;
use std::path::{Path, PathBuf};
use std::sync::{Arc, Mutex};

use crossbeam_channel::{Receiver, Sender};
use lsp_server::{Message, Notification};
use lsp_types::notification::{Notification as _, PublishDiagnostics};
use lsp_types::{
    Diagnostic, DiagnosticRelatedInformation, DiagnosticSeverity, Location, Position,
    PublishDiagnosticsParams, Range, Uri,
};

use super::convert::{self, DocLinks};
use super::position::{Lines, Units};
use super::{uri, Analysis};
use crate::check::{check_document, STDIN_NAME};
use crate::config_file::{ConfigError, Resolver, Settings};
use crate::model::Document;
use crate::report::FileReport;

/// What the main loop asks of the checking thread.
pub enum Job {
    /// Check this text of a document.
    Check {
        uri: Uri,
        version: i32,
        text: Arc<String>,
    },
    /// The document was closed: clear its diagnostics.
    Close(Uri),
    /// The settings changed: check every open document again.
    Settings(Settings),
}

/// Everything the checking thread needs.
pub struct Worker {
    pub jobs: Receiver<Job>,
    pub out: Sender<Message>,
    pub analyses: Arc<Mutex<HashMap<Uri, Arc<Analysis>>>>,
    pub settings: Settings,
    pub units: Units,
    pub links: Arc<DocLinks>,
    /// The workspace folder: the tree deep-level references are read from.
    pub root: Option<PathBuf>,
}

impl Worker {
    // A Uri's hash and equality are those of its text; its interior cache changes neither.
    #[allow(clippy::mutable_key_type)]
    pub fn run(mut self) {
        let mut texts: HashMap<Uri, (i32, Arc<String>)> = HashMap::new();
        while let Ok(first) = self.jobs.recv() {
            // Everything queued meanwhile, oldest first: the newest text of each wins.
            let mut due: Vec<Uri> = Vec::new();
            for job in std::iter::once(first).chain(self.jobs.try_iter()) {
                match job {
                    Job::Check { uri, version, text } => {
                        texts.insert(uri.clone(), (version, text));
                        due.retain(|u| u != &uri);
                        due.push(uri);
                    }
                    Job::Close(uri) => {
                        texts.remove(&uri);
                        due.retain(|u| u != &uri);
                        self.lock().remove(&uri);
                        self.publish(uri, Vec::new(), None);
                    }
                    Job::Settings(settings) => {
                        self.settings = settings;
                        due = texts.keys().cloned().collect();
                    }
                }
            }
            for uri in due {
                if let Some((version, text)) = texts.get(&uri).cloned() {
                    self.check(uri, version, &text);
                }
            }
        }
    }

    fn lock(&self) -> std::sync::MutexGuard<'_, HashMap<Uri, Arc<Analysis>>> {
        self.analyses.lock().unwrap_or_else(|e| e.into_inner())
    }

    fn check(&self, uri: Uri, version: i32, text: &str) {
        let path = uri::to_path(&uri);
        let mut effective = match Resolver::new(None, self.settings.clone())
            .and_then(|mut r| r.for_file(path.as_deref()))
        {
            Ok(effective) => effective,
            Err(error) => {
                let diagnostic = config_error(&error);
                self.publish(uri, vec![diagnostic], Some(version));
                return;
            }
        };
        effective.check.root = path.as_deref().map(|p| self.root_for(p));
        let name = path
            .as_ref()
            .map_or(STDIN_NAME.to_string(), |p| p.display().to_string());
        let config = effective.check;
        // A panic in a rule loses this check, not the server.
        let checked = std::panic::catch_unwind(|| {
            let checked = check_document(&name, text.as_bytes(), &config);
            (checked.report, checked.document, checked.text.into_owned())
        });
        let Ok((report, document, checked_text)) = checked else {
            let internal = Diagnostic {
                message: format!("x3dcheck: internal error while checking {name}"),
                severity: Some(DiagnosticSeverity::ERROR),
                source: Some("x3dcheck".into()),
                ..Diagnostic::default()
            };
            self.publish(uri, vec![internal], Some(version));
            return;
        };
        let diagnostics = {
            let lines = Lines::new(&checked_text, self.units);
            report
                .diagnostics
                .iter()
                .map(|d| convert::diagnostic(d, &uri, &lines, &self.links))
                .collect()
        };
        let mut analyses = self.lock();
        let modelled = match document {
            Some(_) => None,
            None => analyses
                .get(&uri)
                .and_then(|previous| match previous.document {
                    Some(_) => Some(previous.clone()),
                    None => previous.modelled.clone(),
                }),
        };
        let analysis = Analysis::new(version, checked_text, document, report, modelled);
        analyses.insert(uri.clone(), Arc::new(analysis));
        drop(analyses);
        self.publish(uri, diagnostics, Some(version));
    }

    /// The workspace folder when the file lies in it, else the file's directory (as the
    /// command line takes the current directory).
    fn root_for(&self, file: &Path) -> PathBuf {
        match &self.root {
            Some(root) if file.starts_with(root) => root.clone(),
            _ => file.parent().map(Path::to_path_buf).unwrap_or_default(),
        }
    }

    fn publish(&self, uri: Uri, diagnostics: Vec<Diagnostic>, version: Option<i32>) {
        let params = PublishDiagnosticsParams {
            uri,
            diagnostics,
            version,
        };
        let notification = Notification::new(PublishDiagnostics::METHOD.to_string(), params);
        // The main loop is gone when this fails: the server is exiting.
        let _ = self.out.send(Message::Notification(notification));
    }
}

/// A broken x3dcheck.toml, shown on the scene it stops (at its start), pointing at the
/// place in the configuration file.
fn config_error(error: &ConfigError) -> Diagnostic {
    let related = uri::from_path(&error.path).map(|uri| {
        let at = Position::new(
            error.line.saturating_sub(1) as u32,
            error.column.saturating_sub(1) as u32,
        );
        vec![DiagnosticRelatedInformation {
            location: Location::new(uri, Range::new(at, at)),
            message: error.message.clone(),
        }]
    });
    Diagnostic {
        range: Range::default(),
        severity: Some(DiagnosticSeverity::ERROR),
        source: Some("x3dcheck".into()),
        message: format!("x3dcheck.toml: {error}"),
        related_information: related,
        ..Diagnostic::default()
    }
}

impl Analysis {
    fn new(
        version: i32,
        text: Vec<u8>,
        document: Option<Document>,
        report: FileReport,
        modelled: Option<Arc<Analysis>>,
    ) -> Self {
        Analysis {
            version,
            text,
            document,
            report,
            modelled,
        }
    }
}
