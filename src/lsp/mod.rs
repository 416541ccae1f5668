//! `x3dcheck server`: a Language Server Protocol server over stdio, on rust-analyzer's
//! `lsp-server` scaffold. The main loop keeps the open documents' texts and answers
//! requests from the newest check of each; checking runs on its own thread (`worker`),
//! with the command line's entry point ([`crate::check::check_document`]) and the
//! x3dcheck.toml that applies to the file.
//!
//! Features: diagnostics (on open and change), hover (`hover`), completion
//! (`complete`), go to definition and document symbols (`navigate`), and code actions
//! from the findings' fixes (`convert::code_actions`).

mod complete;
mod context;
mod convert;
mod hover;
mod navigate;
mod position;
mod uri;
mod worker;

use std::collections::HashMap;
use std::sync::{Arc, Mutex};

use crossbeam_channel::Sender;
use lsp_server::{Connection, Message, Notification, Request, Response};
use lsp_types::notification::{
    DidChangeConfiguration, DidChangeTextDocument, DidCloseTextDocument, DidOpenTextDocument,
    Notification as _,
};
use lsp_types::request::{
    CodeActionRequest, Completion, DocumentSymbolRequest, GotoDefinition, HoverRequest,
    Request as _,
};
use lsp_types::{
    CodeActionProviderCapability, CompletionOptions, HoverProviderCapability, InitializeParams,
    InitializeResult, OneOf, PositionEncodingKind, ServerCapabilities, ServerInfo,
    TextDocumentSyncCapability, TextDocumentSyncKind, Uri,
};
use serde::de::DeserializeOwned;

use crate::config_file::Settings;
use crate::diagnostic::Level;
use crate::model::Document;
use crate::report::FileReport;
use position::{Lines, Units};
use worker::{Job, Worker};

/// The newest check of one document: the text it checked (decoded: what the spans are
/// offsets into), the model read and the report.
pub struct Analysis {
    pub version: i32,
    pub text: Vec<u8>,
    pub document: Option<Document>,
    pub report: FileReport,
    /// When the reader stopped (no document, as while an author is typing): the newest
    /// check that read one, which completion takes DEF names and the version from.
    pub modelled: Option<Arc<Analysis>>,
}

impl Analysis {
    /// This check if it read a document, else the newest one that did.
    pub fn with_document(&self) -> Option<&Analysis> {
        match self.document {
            Some(_) => Some(self),
            None => self.modelled.as_deref(),
        }
    }
}

/// Runs the server on stdin/stdout until the client says `exit`.
pub fn run() -> Result<(), String> {
    let (connection, io_threads) = Connection::stdio();
    serve(&connection)?;
    // The loop ends on `exit`; dropping the connection lets the writer thread finish.
    drop(connection);
    io_threads.join().map_err(|e| e.to_string())
}

fn serve(connection: &Connection) -> Result<(), String> {
    let (id, params) = connection.initialize_start().map_err(|e| e.to_string())?;
    let params: InitializeParams = serde_json::from_value(params).map_err(|e| e.to_string())?;
    let offers_utf8 = params
        .capabilities
        .general
        .as_ref()
        .and_then(|g| g.position_encodings.as_ref())
        .is_some_and(|encodings| encodings.contains(&PositionEncodingKind::UTF8));
    let units = if offers_utf8 {
        Units::Utf8
    } else {
        Units::Utf16
    };
    let options = Options::from_json(params.initialization_options.as_ref());
    let result = InitializeResult {
        capabilities: capabilities(units),
        server_info: Some(ServerInfo {
            name: "x3dcheck".into(),
            version: Some(env!("CARGO_PKG_VERSION").into()),
        }),
    };
    connection
        .initialize_finish(id, serde_json::to_value(result).map_err(|e| e.to_string())?)
        .map_err(|e| e.to_string())?;

    #[allow(deprecated)] // root_uri: clients without workspace folders still send it
    let root = params
        .workspace_folders
        .as_ref()
        .and_then(|folders| folders.first())
        .map(|f| f.uri.clone())
        .or(params.root_uri.clone())
        .and_then(|u| uri::to_path(&u));
    let (jobs, receiver) = crossbeam_channel::unbounded();
    let mut server = Server {
        texts: HashMap::new(),
        analyses: Arc::new(Mutex::new(HashMap::new())),
        jobs,
        units,
        links: Arc::new(convert::DocLinks::new(options.rules_doc_url.clone())),
    };
    let worker = Worker {
        jobs: receiver,
        out: connection.sender.clone(),
        analyses: server.analyses.clone(),
        settings: options.settings(),
        units,
        links: server.links.clone(),
        root,
    };
    let checking = std::thread::Builder::new()
        .name("x3dcheck-check".into())
        .spawn(move || worker.run())
        .map_err(|e| e.to_string())?;
    let outcome = server.main_loop(connection);
    drop(server); // closes the job channel, which ends the worker
    let _ = checking.join();
    outcome
}

fn capabilities(units: Units) -> ServerCapabilities {
    ServerCapabilities {
        position_encoding: Some(match units {
            Units::Utf8 => PositionEncodingKind::UTF8,
            Units::Utf16 => PositionEncodingKind::UTF16,
        }),
        text_document_sync: Some(TextDocumentSyncCapability::Kind(TextDocumentSyncKind::FULL)),
        hover_provider: Some(HoverProviderCapability::Simple(true)),
        completion_provider: Some(CompletionOptions {
            trigger_characters: Some(["<", " ", "\"", "'", "@", "-"].map(String::from).to_vec()),
            ..CompletionOptions::default()
        }),
        definition_provider: Some(OneOf::Left(true)),
        document_symbol_provider: Some(OneOf::Left(true)),
        code_action_provider: Some(CodeActionProviderCapability::Simple(true)),
        ..ServerCapabilities::default()
    }
}

/// The client's settings: `initializationOptions`, or `settings.x3dcheck` of
/// `workspace/didChangeConfiguration`. `level` is the check level (standard unless the
/// x3dcheck.toml or this says otherwise); `rulesDocUrl` a template (`{code}`) for the
/// links to rule docs.
#[derive(Default, serde::Deserialize)]
#[serde(rename_all = "camelCase")]
struct Options {
    level: Option<String>,
    rules_doc_url: Option<String>,
}

impl Options {
    fn from_json(value: Option<&serde_json::Value>) -> Options {
        let value = value.map(|v| v.get("x3dcheck").unwrap_or(v));
        value
            .and_then(|v| serde_json::from_value(v.clone()).ok())
            .unwrap_or_default()
    }

    /// The settings laid over the x3dcheck.toml of each file, as the command line's are.
    fn settings(&self) -> Settings {
        let level = match self.level.as_deref() {
            Some("fast") => Some(Level::Fast),
            Some("standard") => Some(Level::Standard),
            Some("deep") => Some(Level::Deep),
            _ => None,
        };
        Settings {
            level,
            ..Settings::default()
        }
    }
}

struct Server {
    /// The open documents' newest texts.
    texts: HashMap<Uri, (i32, Arc<String>)>,
    analyses: Arc<Mutex<HashMap<Uri, Arc<Analysis>>>>,
    jobs: Sender<Job>,
    units: Units,
    links: Arc<convert::DocLinks>,
}

impl Server {
    fn main_loop(&mut self, connection: &Connection) -> Result<(), String> {
        for message in &connection.receiver {
            match message {
                Message::Request(request) => {
                    if connection
                        .handle_shutdown(&request)
                        .map_err(|e| e.to_string())?
                    {
                        return Ok(());
                    }
                    let response = self.respond(request);
                    connection
                        .sender
                        .send(Message::Response(response))
                        .map_err(|e| e.to_string())?;
                }
                Message::Notification(notification) => self.notified(notification),
                Message::Response(_) => {}
            }
        }
        Ok(())
    }

    fn notified(&mut self, notification: Notification) {
        match notification.method.as_str() {
            DidOpenTextDocument::METHOD => {
                if let Some(p) = params::<lsp_types::DidOpenTextDocumentParams>(notification) {
                    let doc = p.text_document;
                    self.open(doc.uri, doc.version, doc.text);
                }
            }
            DidChangeTextDocument::METHOD => {
                if let Some(p) = params::<lsp_types::DidChangeTextDocumentParams>(notification) {
                    // Full sync: the last change holds the whole text.
                    if let Some(change) = p.content_changes.into_iter().last() {
                        self.open(p.text_document.uri, p.text_document.version, change.text);
                    }
                }
            }
            DidCloseTextDocument::METHOD => {
                if let Some(p) = params::<lsp_types::DidCloseTextDocumentParams>(notification) {
                    self.texts.remove(&p.text_document.uri);
                    let _ = self.jobs.send(Job::Close(p.text_document.uri));
                }
            }
            DidChangeConfiguration::METHOD => {
                if let Some(p) = params::<lsp_types::DidChangeConfigurationParams>(notification) {
                    let options = Options::from_json(Some(&p.settings));
                    let _ = self.jobs.send(Job::Settings(options.settings()));
                }
            }
            _ => {}
        }
    }

    fn open(&mut self, uri: Uri, version: i32, text: String) {
        let text = Arc::new(text);
        self.texts.insert(uri.clone(), (version, text.clone()));
        let _ = self.jobs.send(Job::Check { uri, version, text });
    }

    fn respond(&self, request: Request) -> Response {
        let id = request.id.clone();
        let result = match request.method.as_str() {
            HoverRequest::METHOD => self.hover(request),
            Completion::METHOD => self.complete(request),
            GotoDefinition::METHOD => self.definition(request),
            DocumentSymbolRequest::METHOD => self.symbols(request),
            CodeActionRequest::METHOD => self.code_actions(request),
            _ => {
                return Response::new_err(
                    id,
                    lsp_server::ErrorCode::MethodNotFound as i32,
                    format!("x3dcheck server: no method {}", request.method),
                )
            }
        };
        match result {
            Some(value) => Response::new_ok(id, value),
            None => Response::new_ok(id, serde_json::Value::Null),
        }
    }

    /// The newest check of `uri`.
    fn analysis(&self, uri: &Uri) -> Option<Arc<Analysis>> {
        self.analyses
            .lock()
            .unwrap_or_else(|e| e.into_inner())
            .get(uri)
            .cloned()
    }

    fn hover(&self, request: Request) -> Option<serde_json::Value> {
        let p: lsp_types::HoverParams = params_of(request)?;
        let at = p.text_document_position_params;
        let analysis = self.analysis(&at.text_document.uri)?;
        let lines = Lines::new(&analysis.text, self.units);
        let offset = lines.offset(at.position);
        let (span, markdown) = hover::hover(&analysis, offset)?;
        let hover = lsp_types::Hover {
            contents: lsp_types::HoverContents::Markup(lsp_types::MarkupContent {
                kind: lsp_types::MarkupKind::Markdown,
                value: markdown,
            }),
            range: Some(lines.range(span)),
        };
        serde_json::to_value(hover).ok()
    }

    fn complete(&self, request: Request) -> Option<serde_json::Value> {
        let p: lsp_types::CompletionParams = params_of(request)?;
        let at = p.text_document_position;
        let (_, text) = self.texts.get(&at.text_document.uri)?.clone();
        let analysis = self.analysis(&at.text_document.uri);
        let lines = Lines::new(text.as_bytes(), self.units);
        let offset = lines.offset(at.position);
        let start = context::word_start(text.as_bytes(), offset);
        let replaced = lines.range(crate::diagnostic::Span::new(start, offset));
        let items = complete::complete(text.as_bytes(), offset, analysis.as_deref())
            .into_iter()
            .map(|c| c.item(replaced))
            .collect();
        serde_json::to_value(lsp_types::CompletionResponse::Array(items)).ok()
    }

    fn definition(&self, request: Request) -> Option<serde_json::Value> {
        let p: lsp_types::GotoDefinitionParams = params_of(request)?;
        let at = p.text_document_position_params;
        let analysis = self.analysis(&at.text_document.uri)?;
        let lines = Lines::new(&analysis.text, self.units);
        let target = navigate::definition(&analysis, lines.offset(at.position))?;
        let location = lsp_types::Location::new(at.text_document.uri, lines.range(target));
        serde_json::to_value(lsp_types::GotoDefinitionResponse::Scalar(location)).ok()
    }

    fn symbols(&self, request: Request) -> Option<serde_json::Value> {
        let p: lsp_types::DocumentSymbolParams = params_of(request)?;
        let analysis = self.analysis(&p.text_document.uri)?;
        let lines = Lines::new(&analysis.text, self.units);
        let symbols = navigate::symbols(&analysis, &lines);
        serde_json::to_value(lsp_types::DocumentSymbolResponse::Nested(symbols)).ok()
    }

    fn code_actions(&self, request: Request) -> Option<serde_json::Value> {
        let p: lsp_types::CodeActionParams = params_of(request)?;
        let analysis = self.analysis(&p.text_document.uri)?;
        let lines = Lines::new(&analysis.text, self.units);
        let actions = convert::code_actions(
            &analysis.report.diagnostics,
            &p.text_document.uri,
            &lines,
            &p.range,
            &self.links,
        );
        serde_json::to_value(actions).ok()
    }
}

fn params<T: DeserializeOwned>(notification: Notification) -> Option<T> {
    serde_json::from_value(notification.params).ok()
}

fn params_of<T: DeserializeOwned>(request: Request) -> Option<T> {
    serde_json::from_value(request.params).ok()
}
