//! The draw list: everything the GPU part needs and nothing else, produced by
//! [`flatten`](super::flatten). It states its guarantees here and the GPU code relies on
//! them without checking again:
//!
//! - **Camera space origin.** Every position (vertices, light locations, clip planes) is
//!   in world orientation but relative to the eye: the eye is at the origin. World
//!   transforms were composed in f64 and the eye subtracted in f64 before rounding to f32,
//!   so a scene far from the world origin keeps its precision.
//! - **Finite numbers.** Positions, normals, tangents, colours and texture coordinates are
//!   finite; triangles with a non-finite corner were dropped. Normals are unit length or
//!   zero; tangents have a unit (or zero) xyz and a handedness w of ±1.
//! - **Only what is used, complete.** Within a mesh, every attribute present has one entry
//!   per vertex and every index is in range. Normals are present exactly when the shape is
//!   lit, a texture coordinate generator or a cube map needs them; tangents exactly when a lit material
//!   has a normal texture; texture coordinate sets exactly those some texture samples (at
//!   most [`MAX_TEX_COORD_SETS`]), already generated and transformed.
//! - **Resolved materials.** Colours are in [0, 1] (as the lighting equations of clause
//!   17 expect), alpha is 1 − transparency, and every texture reference is an index into
//!   [`DrawList::textures`] with a texture coordinate set of its mesh (a cube map
//!   stage's, into [`DrawList::cube_textures`]: it samples by direction).
//! - **Lights.** At most [`MAX_LIGHTS`] per layer; each mesh says by a bit mask which
//!   lights of its layer reach it (global lights reach all; a scoped light reaches its
//!   group's descendants).
//! - **Layers** (19775-1 35.2): drawn in list order, each over the previous with the
//!   depth cleared, each with its own camera, background, fog and lights, within its
//!   [`Viewport`] of the image. Positions are relative to the eye of their own layer.

use crate::render::cube_map::CubeImage;

/// How many lights a shape can receive; more are reported as not drawn.
pub const MAX_LIGHTS: usize = 16;
/// Texture coordinate sets per mesh; more are reported, and drawn with the first.
pub const MAX_TEX_COORD_SETS: usize = 4;
/// MultiTexture stages drawn; more are reported as not drawn.
pub const MAX_STAGES: usize = 4;
/// ClipPlanes applying to one shape; more are reported as not applied.
pub const MAX_CLIP_PLANES: usize = 4;
/// Sky and ground colours of a Background gradient; more are reported as not drawn.
pub const MAX_GRADIENT: usize = 8;

#[derive(Clone, Debug)]
pub struct DrawList {
    /// In drawing order, the first at the bottom; none (LayerSet.order naming no layer):
    /// a black image.
    pub layers: Vec<Layer>,
    /// The textures of every layer's meshes.
    pub textures: Vec<Texture>,
    /// The cube textures of every layer: Background panoramas and the cube map textures
    /// of meshes (clause 34).
    pub cube_textures: Vec<CubeImage>,
}

impl DrawList {
    /// Every mesh of every layer.
    pub fn meshes(&self) -> impl Iterator<Item = &Mesh> {
        self.layers.iter().flat_map(|l| l.meshes.iter())
    }
}

/// One layer (35.2.3): a scene with its own bindable nodes, drawn over the layers before
/// it regardless of their depth.
#[derive(Clone, Debug)]
pub struct Layer {
    pub camera: Camera,
    /// Where on the image the layer is drawn; its camera's aspect ratio is this
    /// rectangle's (35.4.3).
    pub viewport: Viewport,
    /// Drawn first within the viewport; None: the layers below show through.
    pub background: Option<Background>,
    pub fog: Option<Fog>,
    pub lights: Vec<Light>,
    /// The image-based light of the layer's first EnvironmentLight; its colour,
    /// intensity, ambientIntensity and reach are those of its entry in `lights`.
    pub environment: Option<Environment>,
    pub meshes: Vec<Mesh>,
}

/// A rectangle of the image in fractions of its width and height, from its left and its
/// bottom edge (Viewport.clipBoundary, 35.4.3): 0 ≤ left ≤ right ≤ 1, 0 ≤ bottom ≤ top ≤ 1.
#[derive(Copy, Clone, Debug, PartialEq)]
pub struct Viewport {
    pub left: f32,
    pub right: f32,
    pub bottom: f32,
    pub top: f32,
}

impl Viewport {
    pub const FULL: Viewport = Viewport {
        left: 0.0,
        right: 1.0,
        bottom: 0.0,
        top: 1.0,
    };

    /// The part of this rectangle given in fractions of it (left, right, bottom, top, each
    /// clamped to [0, 1], as a nested Viewport's clipBoundary is).
    pub fn part(&self, [left, right, bottom, top]: [f32; 4]) -> Viewport {
        let unit = |v: f32| if v.is_nan() { 0.0 } else { v.clamp(0.0, 1.0) };
        let (w, h) = (self.right - self.left, self.top - self.bottom);
        let (l, r) = (unit(left), unit(right).max(unit(left)));
        let (b, t) = (unit(bottom), unit(top).max(unit(bottom)));
        Viewport {
            left: self.left + w * l,
            right: self.left + w * r,
            bottom: self.bottom + h * b,
            top: self.bottom + h * t,
        }
    }

    /// The rectangle in whole pixels of a `width` × `height` image: x and y from the top
    /// left, width, height (edges rounded down, as browsers place them).
    pub fn pixels(&self, width: u32, height: u32) -> [u32; 4] {
        let (w, h) = (width as f32, height as f32);
        let x0 = (w * self.left).floor().clamp(0.0, w) as u32;
        let x1 = (w * self.right).floor().clamp(0.0, w) as u32;
        let y0 = (h * self.bottom).floor().clamp(0.0, h) as u32;
        let y1 = (h * self.top).floor().clamp(0.0, h) as u32;
        [
            x0,
            height - y1.max(y0),
            x1.saturating_sub(x0),
            y1.saturating_sub(y0),
        ]
    }
}

/// A camera at the origin.
#[derive(Copy, Clone, Debug)]
pub struct Camera {
    /// Rotation from camera axes (looking down −Z, +Y up) to world axes.
    pub orientation: glam::Quat,
    pub projection: Projection,
    /// 0 < near < far, both finite.
    pub near: f32,
    pub far: f32,
}

#[derive(Copy, Clone, Debug, PartialEq)]
pub enum Projection {
    /// The field of view of the smaller image side, in radians, in (0, π).
    Perspective { field_of_view: f32 },
    /// OrthoViewpoint: the view rectangle (min x, min y, max x, max y) in camera units,
    /// min < max; the smaller image side is widened to keep the aspect ratio.
    Orthographic { rectangle: [f32; 4] },
}

/// The sky and ground of a Background (24.4.1): colours at angles from the zenith (sky)
/// and from the nadir (ground), each list starting at angle 0 and increasing.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Background {
    pub sky: Vec<([f32; 3], f32)>,
    pub ground: Vec<([f32; 3], f32)>,
    /// Rotation from the Background's coordinate system to world axes.
    pub orientation: glam::Quat,
    /// X3D 4 transparency in [0, 1]: how much of the layers below shows through.
    pub transparency: f32,
    /// The panorama (24.4.1): an index into [`DrawList::cube_textures`], drawn over the
    /// sky and ground where its alpha lets it (a missing face is transparent).
    pub panorama: Option<usize>,
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
    /// An EnvironmentLight: its image-based part is the layer's [`Environment`].
    Environment,
}

/// An EnvironmentLight's image-based lighting (X3D 4.1, 17.4): light arriving from every
/// direction of a distant environment, as glTF's EXT_lights_image_based gives it.
#[derive(Clone, Debug)]
pub struct Environment {
    /// Rotation from world axes to the environment's: the inverse of the light's world
    /// rotation composed with its `rotation` field.
    pub from_world: glam::Quat,
    /// `diffuseCoefficients`: the irradiance of the environment as L2 spherical
    /// harmonics, nine RGB coefficients in the order L00, L1−1, L10, L11, L2−2, L2−1, L20,
    /// L21, L22 (glTF's irradianceCoefficients), finite.
    pub irradiance: Option<[[f32; 3]; 9]>,
    /// The environment's radiance (`specularTexture`), in linear light (half floats, or
    /// 8-bit fractions), prefiltered by roughness on the GPU.
    pub specular: Option<CubeImage>,
    /// A precomputed irradiance map over π (`diffuseTexture`), in linear light, sampled
    /// along the normal.
    pub diffuse: Option<CubeImage>,
}

#[derive(Copy, Clone, Debug)]
pub struct Light {
    pub kind: LightKind,
    pub color: [f32; 3],
    /// In [0, 1e15] (flatten::lights::MAX_INTENSITY): beyond, every lit pixel saturates.
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
    /// 0 ≤ beamWidth ≤ cutOffAngle ≤ π/2.
    pub beam_width: f32,
    pub cut_off_angle: f32,
}

#[derive(Copy, Clone, Debug, Default, PartialEq, Eq)]
pub enum Primitive {
    #[default]
    Triangles,
    Lines,
    Points,
}

impl Primitive {
    /// Indices per primitive.
    pub fn arity(self) -> usize {
        match self {
            Primitive::Triangles => 3,
            Primitive::Lines => 2,
            Primitive::Points => 1,
        }
    }
}

#[derive(Clone, Debug)]
pub struct Mesh {
    pub primitive: Primitive,
    pub positions: Vec<[f32; 3]>,
    pub normals: Option<Vec<[f32; 3]>>,
    /// xyz along the normal texture's increasing s, w the handedness of t.
    pub tangents: Option<Vec<[f32; 4]>>,
    /// Per-vertex RGBA from Color (alpha 1) or ColorRGBA; replaces the material's diffuse,
    /// base or emissive colour (17.2.2.3 applyColorPerVertex).
    pub colors: Option<Vec<[f32; 4]>>,
    /// Whether `colors` replace alpha too (ColorRGBA) or only RGB (Color).
    pub colors_have_alpha: bool,
    /// Texture coordinate sets, each with one entry per vertex.
    pub tex_coords: Vec<Vec<[f32; 2]>>,
    pub indices: Vec<u32>,
    pub front: Material,
    /// The material of back faces (12.2.3): the backMaterial, or the front one. None when
    /// back faces are not drawn (solid TRUE).
    pub back: Option<Material>,
    /// The textures of both sides (12.2.3 requires the back material to share them).
    pub textures: Textures,
    /// Bit i: light i reaches this mesh.
    pub light_mask: u32,
    /// Planes (a, b, c, d) relative to the eye: what has a·x + b·y + c·z + d < 0 is cut.
    pub clip_planes: Vec<[f32; 4]>,
    /// The rectangle of the image the mesh is cut to (a Viewport node it lies in, 35.4.3),
    /// within its layer's; None: its layer's.
    pub scissor: Option<Viewport>,
    /// Whether the colour has alpha below 1 anywhere (drawn blended, back to front).
    pub blended: bool,
    /// Alpha below this is discarded (alphaMode MASK); 0 otherwise.
    pub alpha_cutoff: f32,
    /// The width of lines, the size of points (LineProperties, PointProperties).
    pub stroke: Stroke,
}

/// How wide lines and how large points are drawn, in image pixels (12.4.4, 12.4.7): the
/// nominal size is one pixel.
#[derive(Copy, Clone, Debug, PartialEq)]
pub struct Stroke {
    /// At least 1, finite.
    pub size: f32,
    /// Lines: the pattern of 12.4.3 Table 12.3, 1 solid, 2 dashed, 3 dotted, 4
    /// dash-dotted, 5 dash-dot-dot (the ones browsers shall support), laid along each
    /// polyline in image pixels, `size` times longer for wider lines.
    pub linetype: u32,
    /// Points: the size is divided by a + b·r + c·r² (r the distance from the viewer),
    /// then clamped to [min, max]. (1, 0, 0) and [size, size] for lines.
    pub attenuation: [f32; 3],
    pub min: f32,
    pub max: f32,
}

impl Default for Stroke {
    fn default() -> Self {
        Stroke {
            size: 1.0,
            linetype: 1,
            attenuation: [1.0, 0.0, 0.0],
            min: 1.0,
            max: 1.0,
        }
    }
}

#[derive(Copy, Clone, Debug, PartialEq, Eq)]
pub enum LightingModel {
    Unlit,
    Phong,
    Physical,
}

#[derive(Copy, Clone, Debug, PartialEq)]
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
    /// normalScale, non-negative.
    pub normal_scale: f32,
    /// occlusionStrength in [0, 1].
    pub occlusion_strength: f32,
    /// X3D 3.x tables 17.2/17.3: a three- or four-component texture replaces the colour
    /// and sets aside the Color node (else, and always in 4.x, the texture multiplies
    /// it: 17.2.2.3 mixTexture). Its alpha always multiplies 1 − transparency.
    pub texture_replaces_rgb: bool,
    /// Which colour the Phong ambient term scales: X3D 3.x's diffuse factor ODrgb (after
    /// the main texture and the Color node, 3.3 17.2.2.4) when true; X3D 4's
    /// `ambientIntensity × diffuseColor × textureSample(ambientTexture).rgb` (17.2.2.5)
    /// when false. See `plain_surface` in `shader.wgsl`.
    pub ambient_of_diffuse_factor: bool,
}

/// A texture as a material samples it: the image, and the mesh's coordinate set.
#[derive(Copy, Clone, Debug, PartialEq, Eq)]
pub struct TextureRef {
    pub texture: usize,
    pub tex_coords: usize,
}

/// The textures of a mesh by their role in the lighting equations (17.2.2).
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Textures {
    /// The main texture (Material.diffuseTexture, PhysicalMaterial.baseTexture,
    /// UnlitMaterial.emissiveTexture or Appearance.texture): one stage for a single
    /// texture, one per MultiTexture texture (18.4.3).
    pub main: Vec<Stage>,
    /// MultiTexture color and alpha (the FACTOR source and BLENDFACTORALPHA).
    pub factor: [f32; 4],
    pub emissive: Option<TextureRef>,
    pub normal: Option<TextureRef>,
    pub occlusion: Option<TextureRef>,
    /// Material.specularTexture.
    pub specular: Option<TextureRef>,
    /// Material.shininessTexture (its alpha channel is used).
    pub shininess: Option<TextureRef>,
    /// Material.ambientTexture.
    pub ambient: Option<TextureRef>,
    /// PhysicalMaterial.metallicRoughnessTexture (metallic in blue, roughness in green).
    pub metallic_roughness: Option<TextureRef>,
}

/// One texture stage of the main texture (18.4.3 Tables 18.3–18.5).
#[derive(Copy, Clone, Debug, PartialEq, Eq)]
pub struct Stage {
    /// For a cube map stage, `texture.texture` indexes [`DrawList::cube_textures`].
    pub texture: TextureRef,
    /// A cube map texture (clause 34) and the direction it is looked up with; only the
    /// first stage may have one.
    pub cube: Option<CubeLookup>,
    /// The operation on the colour channels, and on alpha.
    pub mode: StageMode,
    pub alpha_mode: StageMode,
    pub source: StageSource,
    pub function: StageFunction,
}

/// The direction a cube map texture is sampled in, per fragment from its normal and its
/// position (34.2: "the three-dimensional texture coordinates (s,t,r) are treated as a
/// direction vector").
#[derive(Copy, Clone, Debug, PartialEq, Eq)]
#[repr(u32)]
pub enum CubeLookup {
    /// The view vector reflected about the normal, in world axes: the environment stays
    /// put as the viewer turns (without a TextureCoordinateGenerator).
    WorldReflection = 1,
    /// TextureCoordinateGenerator CAMERASPACEREFLECTIONVECTOR (Table 18.6).
    CameraReflection,
    /// TextureCoordinateGenerator CAMERASPACENORMAL.
    CameraNormal,
}

impl Stage {
    /// A single texture multiplying the colour (mixTexture of 17.2.2.3).
    pub fn modulate(texture: TextureRef) -> Stage {
        Stage {
            texture,
            cube: None,
            mode: StageMode::Modulate,
            alpha_mode: StageMode::Modulate,
            source: StageSource::Previous,
            function: StageFunction::None,
        }
    }
}

/// Table 18.3. Arg1 is the stage's texture, Arg2 the colour its `source` names.
#[derive(Copy, Clone, Debug, PartialEq, Eq)]
#[repr(u32)]
pub enum StageMode {
    Modulate = 0,
    Replace,
    Modulate2x,
    Modulate4x,
    Add,
    AddSigned,
    AddSigned2x,
    Subtract,
    AddSmooth,
    BlendDiffuseAlpha,
    BlendTextureAlpha,
    BlendFactorAlpha,
    BlendCurrentAlpha,
    ModulateAlphaAddColor,
    ModulateInvAlphaAddColor,
    ModulateInvColorAddAlpha,
    Off,
    SelectArg1,
    SelectArg2,
    DotProduct3,
}

/// Table 18.4: where Arg2 comes from.
#[derive(Copy, Clone, Debug, PartialEq, Eq)]
#[repr(u32)]
pub enum StageSource {
    /// "": the previous stage's result (the material colour for the first stage).
    Previous = 0,
    Diffuse,
    Specular,
    Factor,
}

/// Table 18.5: applied to the texture argument before the mode.
#[derive(Copy, Clone, Debug, PartialEq, Eq)]
#[repr(u32)]
pub enum StageFunction {
    None = 0,
    Complement,
    AlphaReplicate,
}

/// An RGBA8 image with its mipmap chain (level 0 first, rows from the top), and its
/// sampling (18.2.3, 18.4.9).
#[derive(Clone, Debug)]
pub struct Texture {
    pub width: u32,
    pub height: u32,
    /// Level 0 is `width` × `height`; each next level halves both sides (at least 1).
    pub levels: Vec<Vec<u8>>,
    pub wrap_s: Wrap,
    pub wrap_t: Wrap,
    /// Linear filtering when magnified (else nearest).
    pub magnify_linear: bool,
    /// Linear filtering within a level when minified (else nearest).
    pub minify_linear: bool,
    /// Between mipmap levels: None (level 0 only), nearest or linear.
    pub mipmaps: Option<bool>,
    /// 1 (none) to 16.
    pub anisotropy: u16,
}

#[derive(Copy, Clone, Debug, PartialEq, Eq)]
pub enum Wrap {
    Repeat,
    MirroredRepeat,
    Clamp,
}
