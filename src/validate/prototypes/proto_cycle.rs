//! PROTO_CYCLE: a prototype instantiates itself, directly or through other prototypes.

use std::collections::{HashMap, HashSet, VecDeque};
use std::path::PathBuf;
use std::sync::Arc;

use petgraph::algo::tarjan_scc;
use petgraph::graph::{DiGraph, NodeIndex};
use petgraph::visit::EdgeRef;

use super::definitions;
use super::externs::{Externs, Resolved, Tree};
use crate::diagnostic::{Diagnostic, Level};
use crate::library::Library;
use crate::limits::MAX_LIBRARY_FILES;
use crate::model::rules::LIMIT_EXCEEDED;
use crate::model::{Document, NodeId};
use crate::validate::terms::Terms;
use crate::validate::Ctx;

crate::declare_rule! {
    /// ## What it does
    /// Reports a prototype whose definition instantiates the prototype itself: its body (or
    /// the initial value of one of its fields) holds a ProtoInstance (ClassicVRML: a node
    /// statement) of it, directly or through the bodies of other prototypes — prototypes
    /// declared inside a body included. At the deep level the chain is followed into the
    /// files external prototypes resolve to (see EXTERNPROTO_NOT_FOUND), so a cycle through
    /// a library is found too; a chain through a network URL is not followed.
    ///
    /// One finding per group of prototypes that instantiate each other (a strongly
    /// connected component of the graph of prototypes and the instances in their
    /// definitions, found with Tarjan's algorithm, so that no cycle is missed whatever
    /// file it is entered through), at its first prototype of this file, at the instance
    /// that continues the cycle, with the shortest such cycle in the message. A group with
    /// no prototype of this file is reported when its own file is checked.
    ///
    /// ## Why it matters
    /// 4.4.4.3: "instantiation of a prototype inside its own definition is not permitted
    /// (i.e., recursive prototypes are illegal)". Instantiating one never ends: browsers
    /// refuse the scene, stop at a depth limit, or run out of memory.
    ///
    /// ## Example
    /// ```xml
    /// <ProtoDeclare name='Tree'>
    ///   <ProtoBody><Group><ProtoInstance name='Tree'/></Group></ProtoBody>
    /// </ProtoDeclare>
    /// ```
    ///
    /// ## Use instead
    /// Unroll the recursion to a fixed depth with distinct prototypes (Tree0 holds Tree1 …),
    /// or build the structure with a Script.
    ///
    /// ## Clause
    /// 19775-1 4.4.4.3 Prototype scoping rules.
    /// > "A prototype may not be instantiated inside its own implementation (i.e., recursive prototypes are illegal)" (14772-1 4.8.4)
    ///
    /// The flagged prototype is instantiated, directly or through others, in its own body
    /// (wording read in a copy of the 1997 text).
    pub static PROTO_CYCLE = {
        severity: Error,
        level: Standard,
        clause: "4.4.4.3",
        versions: "all",
        check: Some(check),
    }
}

/// A prototype of one of the files the search reached: (file, index in its protos).
type Key = (usize, usize);

/// A file of the search: the checked document (file 0) or a library.
struct File {
    library: Option<Arc<Library>>,
    /// Per prototype, the instances its definition holds (see [`definitions::instances`]).
    instances: Vec<Vec<(NodeId, usize)>>,
    /// Its ExternProtoDeclares resolved (empty below the deep level).
    externs: Externs,
}

struct Graph<'a, 'c> {
    ctx: &'a Ctx<'c>,
    /// The tree libraries resolve in, at the deep level.
    tree: Option<Tree<'a>>,
    files: Vec<File>,
    by_path: HashMap<PathBuf, usize>,
    /// Set when [`MAX_LIBRARY_FILES`] stopped the search: where, reported once.
    exceeded: Option<NodeId>,
}

impl Graph<'_, '_> {
    fn doc(&self, file: usize) -> &Document {
        match &self.files[file].library {
            None => self.ctx.doc,
            Some(library) => library
                .document
                .as_ref()
                .expect("only parsed libraries are added"),
        }
    }

    /// The prototypes `key` instantiates, each with the instance (in `key`'s file).
    fn successors(&mut self, (file, proto): Key) -> Vec<(Key, NodeId)> {
        let list = self.files[file].instances[proto].clone();
        let mut successors = Vec::with_capacity(list.len());
        for (instance, target) in list {
            if let Some(key) = self.target(file, target, instance) {
                successors.push((key, instance));
            }
        }
        successors
    }

    /// The ProtoDeclare an instance of prototype `target` of `file` builds: itself, or the
    /// one an ExternProtoDeclare resolves to.
    fn target(&mut self, file: usize, target: usize, instance: NodeId) -> Option<Key> {
        if !self.doc(file).protos.get(target)?.external {
            return Some((file, target));
        }
        let (library, proto) = match self.files[file].externs.get(target)? {
            Resolved::Found { library, proto, .. } => (library.clone(), *proto),
            _ => return None,
        };
        let Some(library) = library else {
            return Some((file, proto));
        };
        if let Some(&index) = self.by_path.get(&library.path) {
            return Some((index, proto));
        }
        if self.files.len() >= MAX_LIBRARY_FILES {
            self.exceeded.get_or_insert(instance);
            return None;
        }
        let tree = self.tree.as_ref()?;
        let library_doc = library.document.as_ref()?;
        let base = library.path.parent()?.to_path_buf();
        let externs = tree.externs(library_doc, &base);
        let instances = definitions::instances(library_doc);
        self.files.push(File {
            library: Some(library.clone()),
            instances,
            externs,
        });
        let index = self.files.len() - 1;
        self.by_path.insert(library.path.clone(), index);
        Some((index, proto))
    }

    /// `Name`, or `Name (library.x3d)` for a prototype of another file.
    fn label(&self, (file, proto): Key) -> String {
        let name = &self.doc(file).protos[proto].name.text;
        match &self.files[file].library {
            None => format!("`{name}`"),
            Some(library) => {
                let file_name = library.path.file_name().unwrap_or_default();
                format!("`{name}` ({})", file_name.to_string_lossy())
            }
        }
    }
}

fn check(ctx: &mut Ctx) {
    if ctx.doc.protos.is_empty() {
        return;
    }
    // Library files are followed at the deep level only, from a file with a directory.
    let deep = ctx.config.level >= Level::Deep && ctx.doc.protos.iter().any(|p| p.external);
    let tree = match (deep, ctx.base) {
        (true, Some(base)) => Some(Tree::in_dir(base, ctx.config)),
        _ => None,
    };
    let own_path = ctx.file.and_then(|f| f.canonicalize().ok());
    let findings = {
        let ctx_ref: &Ctx = ctx;
        let mut graph = Graph {
            ctx: ctx_ref,
            tree,
            files: vec![File {
                library: None,
                instances: definitions::instances(ctx_ref.doc),
                externs: ctx_ref.externs.clone(),
            }],
            by_path: HashMap::new(),
            exceeded: None,
        };
        // A library that is this very file is this document.
        if let Some(path) = own_path {
            graph.by_path.insert(path, 0);
        }
        let findings = search(&mut graph);
        let exceeded = graph.exceeded.map(|at| {
            Diagnostic::new(
                &LIMIT_EXCEEDED,
                ctx_ref.doc.node(at).name_span,
                format!(
                    "prototypes instantiate prototypes of more than {MAX_LIBRARY_FILES} library files from here; the rest are not followed (PROTO_CYCLE)"
                ),
            )
            .node(at)
        });
        findings.into_iter().chain(exceeded).collect::<Vec<_>>()
    };
    for diagnostic in findings {
        ctx.report(diagnostic);
    }
}

/// Every prototype reachable from this file's, with the instances that lead from one to
/// the next; its strongly connected components (Tarjan's algorithm, `petgraph`) are the
/// groups of prototypes that instantiate each other, each reported once, at its first
/// prototype of the checked file, with the shortest cycle through it.
fn search(graph: &mut Graph) -> Vec<Diagnostic> {
    let mut edges: DiGraph<Key, NodeId> = DiGraph::new();
    let mut index: HashMap<Key, NodeIndex> = HashMap::new();
    let mut pending = VecDeque::new();
    for (proto, decl) in graph.ctx.doc.protos.iter().enumerate() {
        if !decl.external {
            index.insert((0, proto), edges.add_node((0, proto)));
            pending.push_back((0, proto));
        }
    }
    while let Some(key) = pending.pop_front() {
        let from = index[&key];
        for (next, instance) in graph.successors(key) {
            let to = *index.entry(next).or_insert_with(|| {
                pending.push_back(next);
                edges.add_node(next)
            });
            edges.add_edge(from, to, instance);
        }
    }
    let mut findings = Vec::new();
    for component in tarjan_scc(&edges) {
        let cyclic = component.len() > 1 || edges.contains_edge(component[0], component[0]);
        let first = component
            .iter()
            .copied()
            .filter(|&n| edges[n].0 == 0)
            .min_by_key(|&n| edges[n].1);
        if let (true, Some(first)) = (cyclic, first) {
            let members: HashSet<NodeIndex> = component.iter().copied().collect();
            let steps = shortest_cycle(&edges, &members, first);
            findings.push(cycle(graph, &edges, &steps));
        }
    }
    findings
}

/// The shortest cycle from `start` back to it within `members`: the instances followed,
/// each with the prototype it leads from.
fn shortest_cycle(
    edges: &DiGraph<Key, NodeId>,
    members: &HashSet<NodeIndex>,
    start: NodeIndex,
) -> Vec<(NodeIndex, NodeId)> {
    let mut came_from: HashMap<NodeIndex, (NodeIndex, NodeId)> = HashMap::new();
    let mut queue = VecDeque::from([start]);
    while let Some(at) = queue.pop_front() {
        for edge in edges.edges(at) {
            let next = edge.target();
            if !members.contains(&next) {
                continue;
            }
            if next == start {
                let mut steps = vec![(at, *edge.weight())];
                let mut current = at;
                while current != start {
                    let (previous, instance) = came_from[&current];
                    steps.push((previous, instance));
                    current = previous;
                }
                steps.reverse();
                return steps;
            }
            if let std::collections::hash_map::Entry::Vacant(slot) = came_from.entry(next) {
                slot.insert((at, *edge.weight()));
                queue.push_back(next);
            }
        }
    }
    Vec::new()
}

/// The finding for the cycle `steps` (from a prototype of the checked file back to it).
fn cycle(graph: &Graph, edges: &DiGraph<Key, NodeId>, steps: &[(NodeIndex, NodeId)]) -> Diagnostic {
    let (first, instance) = steps[0];
    let key = edges[first];
    let mut chain: Vec<String> = steps.iter().map(|&(n, _)| graph.label(edges[n])).collect();
    chain.push(graph.label(key));
    let doc = graph.ctx.doc;
    let proto = &doc.protos[key.1];
    let kind = Terms::of(doc.encoding).proto();
    let message = if steps.len() == 1 {
        format!(
            "{kind} `{}` instantiates itself in its own definition",
            proto.name.text
        )
    } else {
        format!(
            "{kind} `{}` instantiates itself: {}",
            proto.name.text,
            chain.join(" → ")
        )
    };
    Diagnostic::new(&PROTO_CYCLE, doc.node(instance).name_span, message)
        .node(instance)
        .value(proto.name.text.clone())
        .related(
            proto.name.span,
            format!("`{}` declared here", proto.name.text),
        )
}

#[cfg(test)]
mod tests {
    use crate::config::CheckConfig;
    use crate::diagnostic::Level;

    /// `count` files, each with a prototype whose body holds the next file's; the last
    /// names the first when `closed`.
    fn chain(dir: &std::path::Path, count: usize, closed: bool) {
        std::fs::create_dir_all(dir).unwrap();
        for i in 0..count {
            let next = if i + 1 < count {
                i + 1
            } else if closed {
                0
            } else {
                i
            };
            let scene = format!(
                "<X3D profile='Immersive' version='4.0'><Scene>\
                 <ExternProtoDeclare name='Next' url='\"f{next}.x3d#P{next}\"'/>\
                 <ProtoDeclare name='P{i}'><ProtoBody><Group><ProtoInstance name='Next'/></Group></ProtoBody></ProtoDeclare>\
                 </Scene></X3D>"
            );
            std::fs::write(dir.join(format!("f{i}.x3d")), scene).unwrap();
        }
    }

    fn codes(path: &std::path::Path, level: Level) -> Vec<(String, String)> {
        // These files also load one another (INLINE_CYCLE's finding, and its own limit).
        let config = CheckConfig {
            level,
            ignore: ["INLINE_CYCLE".to_string()].into(),
            ..CheckConfig::default()
        };
        let source = std::fs::read(path).unwrap();
        let report = crate::check::check_source(&path.display().to_string(), &source, &config);
        report
            .diagnostics
            .iter()
            .map(|d| (d.code.to_string(), d.message.clone()))
            .filter(|(code, _)| code != "VALIDATION_INCOMPLETE")
            .collect()
    }

    #[test]
    fn a_cycle_through_library_files_is_found_at_the_deep_level_only() {
        let dir = std::env::temp_dir().join(format!("x3dcheck-cycle-{}", std::process::id()));
        chain(&dir, 5, true);
        let found = codes(&dir.join("f0.x3d"), Level::Deep);
        assert_eq!(found.len(), 1, "{found:?}");
        assert_eq!(found[0].0, "PROTO_CYCLE");
        assert!(
            found[0].1.contains("`P0` → `P1` (f1.x3d) →"),
            "{}",
            found[0].1
        );
        assert!(codes(&dir.join("f0.x3d"), Level::Standard).is_empty());
        std::fs::remove_dir_all(&dir).unwrap();
    }

    #[test]
    fn a_long_chain_of_library_files_stops_at_the_limit() {
        let count = crate::limits::MAX_LIBRARY_FILES + 10;
        let dir = std::env::temp_dir().join(format!("x3dcheck-chain-{}", std::process::id()));
        chain(&dir, count, true);
        let found = codes(&dir.join("f0.x3d"), Level::Deep);
        // The body's instance is also instantiated through the files, until the nesting
        // limit: a LIMIT_EXCEEDED of its own.
        let cycle: Vec<&str> = found
            .iter()
            .filter(|(_, message)| !message.contains("nest deeper"))
            .map(|(code, _)| code.as_str())
            .collect();
        assert_eq!(cycle, ["LIMIT_EXCEEDED"], "the cycle closes past the limit");
        assert!(
            found.iter().any(|(_, m)| m.contains("(PROTO_CYCLE)")),
            "{found:?}"
        );
        std::fs::remove_dir_all(&dir).unwrap();
    }
}
