//! USE_CYCLE: reported by the model builder when a USE stands inside the node it names.
//! The reference is left out of the model, so the graph stays acyclic for every later step.

crate::declare_rule! {
    /// ## What it does
    /// Reports a node that is `USE`d inside itself.
    ///
    /// A Script or shader whose own `field` holds a USE of the Script itself or of a node
    /// around it is not a cycle: scripts reach nodes through such fields, and the scene
    /// graph does not traverse them (19775-1 clause 29, Scripting).
    ///
    /// ## Why it matters
    /// The scene graph is a directed acyclic graph; a cycle makes traversal endless and
    /// browsers reject or hang on it.
    ///
    /// ## Example
    /// ```xml
    /// <Transform DEF='T'>
    ///   <Transform USE='T'/>
    /// </Transform>
    /// ```
    ///
    /// ## Clause
    /// 19775-1 4.3.2 Scene graph hierarchy; 4.4.3 DEF/USE semantics.
    /// > "The transformation hierarchy shall be a directed acyclic graph" (14772-1 4.4.4)
    ///
    /// A node USEd inside itself is its own ancestor, a cycle in that graph (19775-1 4.3.2
    /// calls the scene graph a directed acyclic graph too).
    pub static USE_CYCLE = {
        severity: Error,
        level: Fast,
        clause: "4.4.3",
        versions: "all",
    }
}
