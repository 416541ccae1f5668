//! Every limit x3dcheck keeps so that no input, however hostile, can crash it, hang it or
//! exhaust its memory. Going past one is reported as `LIMIT_EXCEEDED` at the place where it
//! happened, and the part beyond the limit is not read (the check of that file is then
//! incomplete); nothing panics or allocates without bound.
//!
//! Each value stays far above what real scenes need: the largest of the 1,336 real scenes
//! in the shared corpus has 2,516 nodes, 16 attributes on one element, 875 findings and no
//! entity declaration; the benchmark's generated 85 MB scene (six IndexedTriangleSets of
//! 160,000 vertices) has 955,206 values in its largest field. README ("Limits") and the
//! LIMIT_EXCEEDED rule document list the same values: change them together.

/// Bytes of one input. Positions are u32 byte offsets, so a larger file is refused whole
/// (by the command line, and by the readers for callers of the library).
pub const MAX_INPUT_BYTES: usize = u32::MAX as usize;

/// Nodes in the deepest chain of the scene graph, through USE too. Walkers recurse over
/// the graph: this bounds their stack. HAnim skeletons, the deepest common case, nest about
/// 60 levels.
pub const MAX_DEPTH: usize = 1000;

/// Levels of JSON arrays and objects the scanner reads (three per level of nodes: object,
/// `-children` array, node object). Deeper input is malformed JSON to x3dcheck.
pub const MAX_JSON_NESTING: usize = 10_000;

/// Nodes in one document (400 times the largest real scene): each costs a few hundred
/// bytes of model, and rules walk them all.
pub const MAX_NODES: usize = 1_000_000;

/// Nodes that instantiating prototypes may add to a document, at least: the budget is
/// this or [`INSTANCE_AMPLIFICATION`] times the nodes the document writes, whichever is
/// more (the amplification factor of XML parsers against entity expansion). An
/// instance copies only the body nodes that take a value through IS and the nodes above
/// them (the rest is shared), and instances with identical values share one copy, so
/// real scenes need few: the most in the shared corpus is 4,004 (1,001 instantiations,
/// one file). A prototype "billion laughs" (bodies of ten instances of the previous
/// prototype, each passing its own values on) is a small document: it stops here,
/// reported, having cost what a document of this many nodes costs.
pub const MAX_INSTANCE_NODES: usize = 100_000;

/// Copies per written node instantiation may make past [`MAX_INSTANCE_NODES`]: a scene of
/// 100,000 distinct instances of a four-node prototype needs four per instance, so a
/// linear scene passes while the copies stay within a constant factor of the input (a
/// copy costs the rules what a written node costs).
pub const INSTANCE_AMPLIFICATION: usize = 8;

/// Field values (numbers, strings, nodes) those copies may hold: a copied node keeps its
/// own fields, so a body IndexedFaceSet of a million indices with one IS field would
/// otherwise cost 4 MB per distinct instance.
pub const MAX_INSTANCE_VALUES: usize = 1 << 24;

/// Prototype instances nested in prototype bodies that are instantiated, outermost 1.
pub const MAX_PROTO_NESTING: usize = 32;

/// Fields and attributes on one node or element (60 times the most a real scene sets).
/// Field lookups and XML's duplicate-attribute check are linear per element, so this
/// also bounds the time a single element can take.
pub const MAX_FIELDS_PER_NODE: usize = 1000;

/// Values (numbers, strings, nodes, images) in one field: 2^24, 17 times the benchmark's
/// largest field; at most 128 MB for an MFDouble.
pub const MAX_FIELD_VALUES: usize = 1 << 24;

/// Findings kept for one document (11 times the most a real scene has). Each holds a
/// message, a structural path and related places, so a file made of errors could otherwise
/// cost a hundred times its size in memory.
pub const MAX_DIAGNOSTICS: usize = 10_000;

/// Inline suppression comments honoured in one document: each finding is compared with
/// the comments around it, so a file of comments would otherwise cost their number times
/// its findings. Those past the limit are LIMIT_EXCEEDED, once.
pub const MAX_DIRECTIVES: usize = 1000;

/// Bytes that references to entities declared in a DOCTYPE's internal subset may expand
/// to in one document ("billion laughs": ten entities of ten references each stand for
/// 10^10 bytes). No real scene declares an entity; X3D's own DOCTYPE names a DTD by its
/// public id, which is never fetched.
pub const MAX_ENTITY_EXPANSION: usize = 1 << 20;

/// Entities nested in entities (`&a;` whose text holds `&b;` …); a recursive entity ends
/// here too.
pub const MAX_ENTITY_NESTING: usize = 16;

/// The longest piece of Script code parsed (bytes). oxc's parser recurses once per nesting
/// level and has no depth limit of its own, so each parse runs on a thread whose stack can
/// hold the deepest nesting code of this length can write ([`SCRIPT_STACK_PER_BYTE`] per
/// byte); longer code is not parsed (VALIDATION_INCOMPLETE).
pub const MAX_SCRIPT_BYTES: usize = 1 << 19;
/// Stack reserved per byte of Script code (measured: a nesting level costs well under this),
/// on top of [`SCRIPT_STACK_BASE`]. Reserved, not used: pages are touched only as deep as
/// the code nests.
pub const SCRIPT_STACK_PER_BYTE: usize = 2048;
pub const SCRIPT_STACK_BASE: usize = 8 << 20;

/// Prototype library files (the files ExternProtoDeclares name, and those their
/// ExternProtoDeclares name, …) followed from one document at the deep level when looking
/// for prototypes that instantiate themselves. Real libraries name a few others at most.
pub const MAX_LIBRARY_FILES: usize = 256;

/// Pixels on one side of an image the deep checks and the renderer decode. The size is
/// read from the file's header before decoding, so a small file claiming 100000×100000
/// (a decompression bomb) costs nothing.
pub const MAX_IMAGE_SIDE: u32 = 16_384;

/// Bytes one decoded image may take (the decoder's own allocation limit).
pub const MAX_IMAGE_BYTES: u64 = 1 << 30;

/// The decoder's limits: the header's size is checked against them before any pixel is
/// decoded, so a small file claiming 100000×100000 pixels costs nothing.
pub fn image_limits() -> image::Limits {
    let mut limits = image::Limits::default();
    limits.max_image_width = Some(MAX_IMAGE_SIDE);
    limits.max_image_height = Some(MAX_IMAGE_SIDE);
    limits.max_alloc = Some(MAX_IMAGE_BYTES);
    limits
}

/// Corners of one polygon (IndexedFaceSet face, Extrusion cap) the renderer triangulates.
/// Ear clipping (the `earcut` crate) is fast on real faces, but on an adversarial one
/// (a star of thin spikes) its cost grows with the square of the corners: 10,000 take
/// 0.2 s, 50,000 5 s, 200,000 100 s. A larger face is not drawn and reported.
pub const MAX_FACE_CORNERS: usize = 8192;

/// The renderer's budgets (`--render`): past one, the walk of the scene stops or the part
/// is left out, reported as LIMIT_EXCEEDED, and the image shows what was drawn so far.
/// Together they keep a render within seconds and within memory proportional to what it
/// draws, however far DEF/USE expands the scene.
///
/// Node instances the renderer walks: DEF/USE can make a small file stand for 2^199.
pub const MAX_RENDER_NODE_INSTANCES: u64 = 1_000_000;

/// Shape instances drawn: each is a mesh of its own (placed relative to the eye in f64),
/// GPU buffers and a draw call, about 26 KB and 0.3 ms on a software rasterizer whatever
/// its size, so a small file of nested USEs of one Box could ask for a million. The
/// largest real scene has 863 shapes; 65,536 Boxes took 11 s and 950 MB.
pub const MAX_RENDER_SHAPES: usize = 16_384;

/// Triangles, lines and points drawn per pixel of the image, between the two bounds
/// below (each costs about 150 bytes until the frame is drawn).
pub const RENDER_PRIMITIVES_PER_PIXEL: u64 = 16;
pub const MIN_RENDER_PRIMITIVES: u64 = 4_000_000;
pub const MAX_RENDER_PRIMITIVES: u64 = 16_000_000;

/// Times the shapes drawn may cover the image, counted shape by shape whatever hides
/// what (render::flatten::fill): a software rasterizer shades each shape wherever it
/// covers the image, so 300 spheres at one place cost 300 images' worth of shading (on
/// lavapipe about 2.5 million pixels a second with per-pixel lighting: 16 images of
/// 800 × 600 take some 3 s). The real scenes of the shared corpus cover it 5.9 times at
/// most.
pub const RENDER_FILL_IMAGES: u64 = 16;

/// Characters of Text the renderer lays out, over all Text instances of a scene (the
/// most in a real scene of the shared corpus is a few hundred). Text past it is not
/// drawn: a string of ten million characters costs a few bytes of layout per character
/// before the triangle budget could see it (spaces make no triangles at all).
pub const MAX_RENDER_TEXT_CHARACTERS: usize = 100_000;

/// Texture bytes (RGBA8, with mipmaps) the renderer loads, over all textures.
pub const MAX_RENDER_TEXTURE_BYTES: usize = 512 << 20;
