//! The draw list: everything the GPU part needs and nothing else, produced by
//! [`flatten`](super::flatten). It states its guarantees here and the GPU code relies on
//! them without checking again:
//!
//! - **Camera space origin.** Every position (vertices, light locations) is in world
//!   orientation but relative to the eye: the eye is at the origin. World transforms were
//!   composed in f64 and the eye subtracted in f64 before rounding to f32, so a scene far
//!   from the world origin keeps its precision.
//! - **Finite numbers.** Positions, normals, colours and texture coordinates are finite;
//!   triangles with a non-finite corner were dropped. Normals are unit length or zero.
//! - **Complete attributes.** Within a mesh, every attribute present has one entry per
//!   vertex and every index is in range. Normals are present exactly when the material is
//!   lit; texture coordinates exactly when the material has a texture.
//! - **Resolved materials.** Colours are in [0, 1] (as the lighting equations of clause
//!   17 expect), alpha is 1 − transparency, and a texture reference is an index into
//!   [`DrawList::textures`].
//! - **Lights.** At most [`MAX_LIGHTS`]; each mesh says by a bit mask which lights reach
//!   it (global lights reach all; a scoped light reaches its group's descendants).

/// How many lights a shape can receive; more are reported as not drawn.
pub const MAX_LIGHTS: usize = 16;

#[derive(Clone, Debug)]
pub struct DrawList {
    pub camera: Camera,
    pub background: [f32; 3],
    pub fog: Option<Fog>,
    pub lights: Vec<Light>,
    pub meshes: Vec<Mesh>,
    pub textures: Vec<Texture>,
}

/// A perspective camera at the origin.
#[derive(Copy, Clone, Debug)]
pub struct Camera {
    /// Rotation from camera axes (looking down −Z, +Y up) to world axes.
    pub orientation: glam::Quat,
    /// The field of view of the smaller image side, in radians, in (0, π).
    pub field_of_view: f32,
    /// 0 < near < far, both finite.
    pub near: f32,
    pub far: f32,
}

#[derive(Copy, Clone, Debug)]
pub struct Fog {
    pub color: [f32; 3],
    pub exponential: bool,
    /// Positive and finite (a fog with visibilityRange 0 is no fog and is not listed).
    pub visibility_range: f32,
}

#[derive(Copy, Clone, Debug, PartialEq, Eq)]
pub enum LightKind {
    Directional,
    Point,
    Spot,
}

#[derive(Copy, Clone, Debug)]
pub struct Light {
    pub kind: LightKind,
    pub color: [f32; 3],
    /// Non-negative and finite.
    pub intensity: f32,
    pub ambient_intensity: f32,
    /// Relative to the eye (point and spot lights).
    pub location: [f32; 3],
    /// Unit direction the light travels (directional and spot lights).
    pub direction: [f32; 3],
    /// Constant, linear, quadratic; (0, 0, 0) was replaced by (1, 0, 0).
    pub attenuation: [f32; 3],
    /// World-space radius (point and spot lights): beyond it the light has no effect.
    pub radius: f32,
    pub beam_width: f32,
    pub cut_off_angle: f32,
}

#[derive(Copy, Clone, Debug, PartialEq, Eq)]
pub enum Primitive {
    Triangles,
    Lines,
    Points,
}

#[derive(Clone, Debug)]
pub struct Mesh {
    pub primitive: Primitive,
    pub positions: Vec<[f32; 3]>,
    pub normals: Option<Vec<[f32; 3]>>,
    /// Per-vertex RGBA from Color (alpha 1) or ColorRGBA; replaces the material's diffuse,
    /// base or emissive colour (17.2.2.3 applyColorPerVertex).
    pub colors: Option<Vec<[f32; 4]>>,
    /// Already transformed by the TextureTransform.
    pub tex_coords: Option<Vec<[f32; 2]>>,
    pub indices: Vec<u32>,
    pub front: Material,
    /// The material of back faces (12.2.3): the backMaterial, or the front one. None when
    /// back faces are not drawn (solid TRUE).
    pub back: Option<Material>,
    /// Bit i: light i reaches this mesh.
    pub light_mask: u32,
    /// Whether the colour has alpha below 1 anywhere (drawn blended, back to front).
    pub blended: bool,
    /// Alpha below this is discarded (alphaMode MASK); 0 otherwise.
    pub alpha_cutoff: f32,
}

#[derive(Copy, Clone, Debug, PartialEq, Eq)]
pub enum LightingModel {
    Unlit,
    Phong,
    Physical,
}

#[derive(Copy, Clone, Debug)]
pub struct Material {
    pub model: LightingModel,
    /// Material.diffuseColor, PhysicalMaterial.baseColor; unused when unlit.
    pub diffuse: [f32; 3],
    /// emissiveColor (the whole colour of an unlit shape).
    pub emissive: [f32; 3],
    pub specular: [f32; 3],
    pub ambient_intensity: f32,
    /// Phong exponent: shininess × 128.
    pub shininess: f32,
    pub metallic: f32,
    pub roughness: f32,
    /// 1 − transparency.
    pub alpha: f32,
    /// The texture modulating the diffuse, base or emissive colour (12.2.5).
    pub texture: Option<usize>,
    /// X3D 3.x tables 17.2/17.3: a three- or four-component texture replaces the colour
    /// (else, and always in 4.x, the texture multiplies it: 17.2.2.3 mixTexture).
    pub texture_replaces_rgb: bool,
    /// X3D 3.x: a two- or four-component texture's alpha replaces 1 − transparency.
    pub texture_replaces_alpha: bool,
}

/// An RGBA8 image, rows from the top, with its sampling.
#[derive(Clone, Debug)]
pub struct Texture {
    pub width: u32,
    pub height: u32,
    pub rgba: Vec<u8>,
    pub repeat_s: bool,
    pub repeat_t: bool,
    /// Linear filtering (else nearest).
    pub linear: bool,
}
