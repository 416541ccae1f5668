//! Appearance → materials and textures by role. The front material and the back one
//! (backMaterial or TwoSidedMaterial, 12.2.3); the main texture (the material's
//! diffuse/base/emissive texture, else Appearance.texture, possibly a MultiTexture,
//! 12.2.5); the other material textures of the lit models (17.2.2.5, 17.2.2.6); each with
//! the rule that picks its texture coordinates (12.2.4, or the MultiTexture stage order of
//! 18.4.4 and 18.4.5), resolved per Shape in `shape.rs`.

use std::path::Path;

use super::{Context, Walker};
use crate::limits::MAX_RENDER_TEXTURE_BYTES as MAX_TEXTURE_BYTES;
use crate::model::NodeId;
use crate::render::draw_list::{
    LightingModel, Material, StageFunction, StageMode, StageSource, Stroke, MAX_STAGES,
};
use crate::render::fields::{boolean, child, color, float, type_is, unit};
use crate::render::textures;

/// A texture in the draw list.
#[derive(Copy, Clone, Debug)]
pub struct LoadedTexture {
    pub index: usize,
    /// 1 intensity, 2 intensity + alpha, 3 RGB, 4 RGBA.
    pub channels: u8,
    pub translucent: bool,
    /// A cube map texture (clause 34): `index` is into the cube textures.
    pub cube: bool,
}

/// Which texture coordinates and transformation a texture takes.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Rule {
    /// An xxxTextureMapping (12.2.4); "" for Appearance.texture (the first of each list).
    Mapping(String),
    /// MultiTexture stage i: coordinates i (or the last), transformation i (or none).
    Stage(usize),
}

/// What a texture does in the lighting equations.
#[derive(Copy, Clone, Debug, PartialEq, Eq)]
pub enum Role {
    /// A stage of the main texture.
    Stage {
        mode: StageMode,
        alpha_mode: StageMode,
        source: StageSource,
        function: StageFunction,
    },
    Emissive,
    Normal,
    Occlusion,
    Specular,
    Shininess,
    Ambient,
    MetallicRoughness,
}

#[derive(Clone, Debug)]
pub struct TextureUse {
    pub role: Role,
    pub texture: LoadedTexture,
    pub rule: Rule,
}

pub struct Look {
    pub front: Material,
    pub back: Option<Material>,
    pub textures: Vec<TextureUse>,
    /// MultiTexture color and alpha.
    pub factor: [f32; 4],
    pub alpha_mode: String,
    pub alpha_cutoff: f32,
    /// LineProperties (lines), PointProperties (points).
    pub line: Stroke,
    pub point: Stroke,
}

impl Look {
    /// Whether the main texture has texels with alpha below 1.
    pub fn translucent_texture(&self) -> bool {
        self.textures
            .iter()
            .any(|t| matches!(t.role, Role::Stage { .. }) && t.texture.translucent)
    }
}

/// The material fields holding textures other than the main one, per lighting model.
fn role_fields(model: LightingModel) -> &'static [(&'static str, Role)] {
    match model {
        LightingModel::Unlit => &[],
        LightingModel::Phong => &[
            ("emissiveTexture", Role::Emissive),
            ("normalTexture", Role::Normal),
            ("occlusionTexture", Role::Occlusion),
            ("specularTexture", Role::Specular),
            ("shininessTexture", Role::Shininess),
            ("ambientTexture", Role::Ambient),
        ],
        LightingModel::Physical => &[
            ("emissiveTexture", Role::Emissive),
            ("normalTexture", Role::Normal),
            ("occlusionTexture", Role::Occlusion),
            ("metallicRoughnessTexture", Role::MetallicRoughness),
        ],
    }
}

/// The main texture field of a one-sided material (12.2.5).
fn main_field(model: LightingModel) -> &'static str {
    match model {
        LightingModel::Unlit => "emissiveTexture",
        LightingModel::Phong => "diffuseTexture",
        LightingModel::Physical => "baseTexture",
    }
}

impl Walker<'_> {
    pub(super) fn appearance(&mut self, context: Context, appearance: Option<NodeId>) -> Look {
        let doc = context.doc;
        let mut look = Look {
            front: default_unlit(),
            back: None,
            textures: Vec::new(),
            factor: [1.0; 4],
            alpha_mode: "AUTO".to_string(),
            alpha_cutoff: 0.5,
            line: Stroke::default(),
            point: Stroke::default(),
        };
        let Some(appearance) = appearance else {
            return look;
        };
        look.alpha_mode = doc
            .string_of(appearance, "alphaMode")
            .unwrap_or_else(|| "AUTO".into());
        look.alpha_cutoff = unit(float(doc, appearance, "alphaCutoff", 0.5));
        for field in ["shaders", "fillProperties"] {
            if !doc.node(appearance).children(field).is_empty() {
                self.note(
                    context,
                    appearance,
                    format!("Appearance.{field} is not applied"),
                );
            }
        }
        if let Some(line) = child(doc, appearance, "lineProperties") {
            look.line = self.line_properties(context, line);
        }
        if let Some(point) = child(doc, appearance, "pointProperties") {
            look.point = point_properties(doc, point);
        }
        let material = child(doc, appearance, "material");
        if let Some(material) = material {
            let (front, back) = self.material(context, material);
            look.front = front;
            look.back = back;
        }
        let back_material = child(doc, appearance, "backMaterial");
        if let Some(back_material) = back_material {
            look.back = Some(self.material(context, back_material).0);
            let front_textures = material
                .map(|m| self.material_textures(context, m))
                .unwrap_or_default();
            if self.material_textures(context, back_material) != front_textures {
                // 12.2.3 requires the same textures and mappings on both sides.
                self.note(
                    context,
                    back_material,
                    "the backMaterial's textures differ from the material's: both sides are drawn with the material's".into(),
                );
            }
        }
        // The main texture: the material's own, else Appearance.texture (12.2.5).
        let model = look.front.model;
        let one_sided = material.filter(|&m| is_one_sided(doc, m));
        let own_main = one_sided.and_then(|m| {
            let field = main_field(model);
            child(doc, m, field).map(|t| (t, mapping(doc, m, field)))
        });
        match own_main {
            // An X3D 4 field, so X3D 4's mixTexture even in a 3.x document.
            Some((texture, mapping)) => {
                self.main_single(context, texture, Rule::Mapping(mapping), false, &mut look)
            }
            None => match child(doc, appearance, "texture") {
                Some(t) if type_is(doc, t, "MultiTexture") => {
                    self.multi_texture(context, t, &mut look)
                }
                Some(t) => {
                    let replaces = self.options.x3d_version_3;
                    self.main_single(
                        context,
                        t,
                        Rule::Mapping(String::new()),
                        replaces,
                        &mut look,
                    )
                }
                None => {}
            },
        }
        if let Some(material) = one_sided {
            for &(field, role) in role_fields(model) {
                if let Some(texture) = child(doc, material, field) {
                    if let Some(loaded) = self.texture(context, texture) {
                        look.textures.push(TextureUse {
                            role,
                            texture: loaded,
                            rule: Rule::Mapping(mapping(doc, material, field)),
                        });
                    }
                }
            }
        }
        look
    }

    /// LineProperties (12.4.4): when applied, linewidthScaleFactor times the nominal
    /// one-pixel width (at least the minimum, one pixel) and linetypes 1 to 5, the ones
    /// browsers shall support (12.4.3); the other registered ones (arrows, chain lines,
    /// user patterns) are noted and drawn solid, as unsupported values shall be.
    fn line_properties(&mut self, context: Context, id: NodeId) -> Stroke {
        let doc = context.doc;
        if !boolean(doc, id, "applied", true) {
            return Stroke::default();
        }
        let linetype = match doc.i32_of(id, "linetype").unwrap_or(1) {
            supported @ 1..=5 => supported as u32,
            other => {
                self.note(
                    context,
                    id,
                    format!("LineProperties linetype {other} is drawn solid"),
                );
                1
            }
        };
        let size = float(doc, id, "linewidthScaleFactor", 0.0).clamp(1.0, MAX_STROKE);
        Stroke {
            size,
            linetype,
            min: size,
            max: size,
            ..Stroke::default()
        }
    }

    /// The texture nodes and mappings of a material's texture fields, to compare sides
    /// (the fields the document sets, those of X3D 4 in a 3.x document too).
    fn material_textures(&self, context: Context, material: NodeId) -> Vec<(NodeId, String)> {
        let doc = context.doc;
        doc.node(material)
            .fields
            .iter()
            .map(|f| f.name())
            .filter(|name| name.ends_with("Texture"))
            .filter_map(|name| {
                child(doc, material, name).map(|t| (t, mapping(doc, material, name)))
            })
            .collect()
    }

    /// A single main texture; `replaces`: by the X3D 3.x tables (Appearance.texture of a
    /// 3.x document), else multiplying the colour.
    fn main_single(
        &mut self,
        context: Context,
        texture: NodeId,
        rule: Rule,
        replaces: bool,
        look: &mut Look,
    ) {
        let Some(loaded) = self.texture(context, texture) else {
            return;
        };
        if replaces {
            // 17.2.2.2 (3.x tables 17.2 and 17.3): an RGB texture replaces the diffuse
            // colour (and the Color node, 11.4.2); its alpha, as every texture's,
            // modulates 1 − transparency (17.2.2.3's text; the shader's mix_texture).
            for m in std::iter::once(&mut look.front).chain(look.back.as_mut()) {
                m.texture_replaces_rgb = loaded.channels >= 3;
            }
        }
        look.textures.push(TextureUse {
            role: Role::Stage {
                mode: StageMode::Modulate,
                alpha_mode: StageMode::Modulate,
                source: StageSource::Previous,
                function: StageFunction::None,
            },
            texture: loaded,
            rule,
        });
    }

    /// MultiTexture (18.4.3): one stage per texture with its mode, source and function. A
    /// mode may name the colour and the alpha operation apart, "MODULATE,REPLACE" (the
    /// example under Table 18.3) or "MODULATE / REPLACE" (as Castle Game Engine writes it).
    fn multi_texture(&mut self, context: Context, multi: NodeId, look: &mut Look) {
        let doc = context.doc;
        let strings = |field: &str| -> Vec<String> {
            doc.value_of(multi, field)
                .and_then(|v| v.as_strings().map(<[String]>::to_vec))
                .unwrap_or_default()
        };
        let (modes, sources, functions) = (strings("mode"), strings("source"), strings("function"));
        let [r, g, b] = color(doc, multi, "color", [1.0; 3]);
        look.factor = [r, g, b, unit(float(doc, multi, "alpha", 1.0))];
        let stages: Vec<NodeId> = doc
            .node(multi)
            .children("texture")
            .iter()
            .map(|c| c.node)
            .collect();
        if stages.len() > MAX_STAGES {
            self.note(
                context,
                multi,
                format!("MultiTexture: textures beyond the first {MAX_STAGES} are not drawn"),
            );
        }
        for (i, &texture) in stages.iter().enumerate().take(MAX_STAGES) {
            if type_is(doc, texture, "MultiTexture") {
                self.note(
                    context,
                    texture,
                    "a MultiTexture inside a MultiTexture is not drawn".into(),
                );
                continue;
            }
            let Some(loaded) = self.texture(context, texture) else {
                continue;
            };
            let (mode, alpha_mode) = match modes
                .get(i)
                .map(String::as_str)
                .unwrap_or("MODULATE")
                .split_once([',', '/'])
            {
                Some((rgb, alpha)) => (stage_mode(rgb.trim()), stage_mode(alpha.trim())),
                None => {
                    let m = stage_mode(modes.get(i).map_or("MODULATE", String::as_str));
                    (m, m)
                }
            };
            let (Some(mode), Some(alpha_mode)) = (mode, alpha_mode) else {
                self.note(
                    context,
                    multi,
                    format!(
                        "MultiTexture mode `{}` is not drawn; MODULATE is used",
                        modes[i]
                    ),
                );
                look.textures.push(TextureUse {
                    role: Role::Stage {
                        mode: StageMode::Modulate,
                        alpha_mode: StageMode::Modulate,
                        source: StageSource::Previous,
                        function: StageFunction::None,
                    },
                    texture: loaded,
                    rule: Rule::Stage(i),
                });
                continue;
            };
            let source = match sources.get(i).map(String::as_str).unwrap_or("") {
                "DIFFUSE" => StageSource::Diffuse,
                "SPECULAR" => StageSource::Specular,
                "FACTOR" => StageSource::Factor,
                _ => StageSource::Previous,
            };
            let function = match functions.get(i).map(String::as_str).unwrap_or("") {
                "COMPLEMENT" => StageFunction::Complement,
                "ALPHAREPLICATE" => StageFunction::AlphaReplicate,
                _ => StageFunction::None,
            };
            look.textures.push(TextureUse {
                role: Role::Stage {
                    mode,
                    alpha_mode,
                    source,
                    function,
                },
                texture: loaded,
                rule: Rule::Stage(i),
            });
        }
    }

    /// A single-image texture in the draw list (loaded once per node), or None, noted.
    fn texture(&mut self, context: Context, texture: NodeId) -> Option<LoadedTexture> {
        let key = (context.serial, texture);
        if let Some(entry) = self.texture_cache.get(&key) {
            return *entry;
        }
        if context.doc.node(texture).is_a("X3DEnvironmentTextureNode") {
            let loaded = self.cube_map_texture(context, texture);
            self.texture_cache.insert(key, loaded);
            return loaded;
        }
        let loaded = match self.load_texture(context, texture) {
            Ok(loaded) => {
                let bytes: usize = loaded.texture.levels.iter().map(Vec::len).sum();
                if self.spent.texture_bytes + bytes > MAX_TEXTURE_BYTES {
                    let mib = MAX_TEXTURE_BYTES >> 20;
                    self.note(
                        context,
                        texture,
                        format!("texture not drawn: the textures would take more than {mib} MiB"),
                    );
                    None
                } else {
                    self.spent.texture_bytes += bytes;
                    self.textures.push(loaded.texture);
                    Some(LoadedTexture {
                        index: self.textures.len() - 1,
                        channels: loaded.channels,
                        translucent: loaded.translucent,
                        cube: false,
                    })
                }
            }
            Err(not_drawn) => {
                self.push_note(context, texture, not_drawn.message, not_drawn.limit);
                None
            }
        };
        self.texture_cache.insert(key, loaded);
        loaded
    }

    /// A cube map texture node in the cube textures, or None, noted. A
    /// GeneratedCubeMapTexture (the scene seen from the shape) is not rendered into: it
    /// is drawn as the bound Background's panorama, the scene at infinity, when there is
    /// one.
    fn cube_map_texture(&mut self, context: Context, texture: NodeId) -> Option<LoadedTexture> {
        let doc = context.doc;
        let name = doc.node(texture).type_name();
        let index = if name == "GeneratedCubeMapTexture" {
            let panorama = self
                .environment
                .background
                .as_ref()
                .and_then(|b| b.panorama);
            let message = match panorama {
                Some(_) => "GeneratedCubeMapTexture is drawn as the Background's panorama: the shapes around it are not rendered into it",
                None => "GeneratedCubeMapTexture is not drawn: the shapes around it are not rendered into it, and no Background panorama stands in",
            };
            self.note(context, texture, message.into());
            panorama?
        } else {
            let loaded = super::super::cube_map::load(
                doc,
                texture,
                context.base,
                &self.options.root,
                self.cube_side(),
            );
            match loaded {
                Ok(cube) => self.add_cube(context, texture, cube)?,
                Err(not_drawn) => {
                    self.push_note(context, texture, not_drawn.message, not_drawn.limit);
                    return None;
                }
            }
        };
        let translucent = self.cube_textures[index].translucent;
        Some(LoadedTexture {
            index,
            channels: if translucent { 4 } else { 3 },
            translucent,
            cube: true,
        })
    }

    /// The largest cube face side loaded: the image's larger side (rounded up to a power
    /// of two), which a face seen at a right angle of view fills; more texels would not
    /// show.
    pub(super) fn cube_side(&self) -> u32 {
        let (width, height) = self.options.image;
        width.max(height).max(1).next_power_of_two()
    }

    /// Adds a cube texture within the texture budget; None, noted, past it.
    pub(super) fn add_cube(
        &mut self,
        context: Context,
        node: NodeId,
        cube: super::super::cube_map::CubeImage,
    ) -> Option<usize> {
        if !self.spend_on_cube(context, node, cube.bytes()) {
            return None;
        }
        self.cube_textures.push(cube);
        Some(self.cube_textures.len() - 1)
    }

    /// Counts a cube texture's bytes against the texture budget; false, noted, past it.
    pub(super) fn spend_on_cube(&mut self, context: Context, node: NodeId, bytes: usize) -> bool {
        if self.spent.texture_bytes + bytes > MAX_TEXTURE_BYTES {
            let mib = MAX_TEXTURE_BYTES >> 20;
            let message =
                format!("cube texture not drawn: the textures would take more than {mib} MiB");
            self.note(context, node, message);
            return false;
        }
        self.spent.texture_bytes += bytes;
        true
    }

    /// The image of `texture`. A texture of an external prototype's body (another file) is
    /// looked for next to that file first, as browsers do, then next to the document that
    /// instantiates the prototype (the base VRML97 14772-1 4.5.3 names), noted when only
    /// there: browsers differ on it.
    fn load_texture(
        &mut self,
        context: Context,
        texture: NodeId,
    ) -> Result<textures::Loaded, textures::NotDrawn> {
        let doc = context.doc;
        let root = &self.options.root;
        let Some(library) = doc.library_file_of(texture) else {
            return textures::load(doc, texture, context.base, root);
        };
        let library_dir = library.parent().unwrap_or(Path::new("."));
        let first = match textures::load(doc, texture, library_dir, root) {
            Ok(loaded) => return Ok(loaded),
            Err(first) => first,
        };
        match textures::load(doc, texture, context.base, root) {
            Ok(loaded) => {
                let file = library.file_name().unwrap_or_default().to_string_lossy();
                self.note(
                    context,
                    texture,
                    format!(
                        "{} found only relative to the scene that instantiates the prototype, not to the prototype's file {file}: browsers that resolve it against the prototype's file draw no texture",
                        doc.node(texture).type_name()
                    ),
                );
                Ok(loaded)
            }
            Err(_) => Err(first),
        }
    }

    /// The front material and, for TwoSidedMaterial, the back one.
    fn material(&mut self, context: Context, id: NodeId) -> (Material, Option<Material>) {
        let doc = context.doc;
        let alpha = |field: &str| 1.0 - unit(float(doc, id, field, 0.0));
        let name = doc.node(id).type_name();
        let version_3 = self.options.x3d_version_3;
        let shared = |m: Material| Material {
            normal_scale: float(doc, id, "normalScale", 1.0).max(0.0),
            occlusion_strength: unit(float(doc, id, "occlusionStrength", 1.0)),
            ..m
        };
        let phong = |prefix: &str| {
            let field = |f: &str| {
                if prefix.is_empty() {
                    f.to_string()
                } else {
                    let mut c = f.chars();
                    let first = c.next().map(|c| c.to_ascii_uppercase()).unwrap_or('x');
                    format!("{prefix}{first}{}", c.as_str())
                }
            };
            Material {
                model: LightingModel::Phong,
                diffuse: color(doc, id, &field("diffuseColor"), [0.8; 3]),
                emissive: color(doc, id, &field("emissiveColor"), [0.0; 3]),
                specular: color(doc, id, &field("specularColor"), [0.0; 3]),
                ambient_intensity: unit(float(doc, id, &field("ambientIntensity"), 0.2)),
                shininess: unit(float(doc, id, &field("shininess"), 0.2)) * 128.0,
                alpha: alpha(&field("transparency")),
                ambient_of_diffuse_factor: version_3,
                ..default_unlit()
            }
        };
        match name {
            "Material" => (shared(phong("")), None),
            "TwoSidedMaterial" => {
                let front = phong("");
                let back = if boolean(doc, id, "separateBackColor", false) {
                    phong("back")
                } else {
                    front
                };
                (front, Some(back))
            }
            "PhysicalMaterial" => (
                shared(Material {
                    model: LightingModel::Physical,
                    diffuse: color(doc, id, "baseColor", [1.0; 3]),
                    emissive: color(doc, id, "emissiveColor", [0.0; 3]),
                    metallic: unit(float(doc, id, "metallic", 1.0)),
                    roughness: unit(float(doc, id, "roughness", 1.0)),
                    alpha: alpha("transparency"),
                    ..default_unlit()
                }),
                None,
            ),
            "UnlitMaterial" => (
                Material {
                    emissive: color(doc, id, "emissiveColor", [1.0; 3]),
                    alpha: alpha("transparency"),
                    ..default_unlit()
                },
                None,
            ),
            other => {
                self.note(
                    context,
                    id,
                    format!("{other} is not drawn; drawn unlit white"),
                );
                (default_unlit(), None)
            }
        }
    }
}

/// The widest line and largest point drawn, in pixels.
const MAX_STROKE: f32 = 256.0;

/// PointProperties (12.4.7): the nominal one-pixel size times pointSizeScaleFactor,
/// attenuated with distance, clamped to [pointSizeMinValue, pointSizeMaxValue] × 1 pixel.
fn point_properties(doc: &crate::model::Document, id: NodeId) -> Stroke {
    let bound = |name: &str| float(doc, id, name, 1.0).clamp(0.0, MAX_STROKE);
    let (min, max) = (bound("pointSizeMinValue"), bound("pointSizeMaxValue"));
    let mut attenuation =
        crate::render::fields::vec3(doc, id, "attenuation", [1.0, 0.0, 0.0]).map(|c| c.max(0.0));
    if attenuation == [0.0; 3] {
        attenuation = [1.0, 0.0, 0.0];
    }
    Stroke {
        size: float(doc, id, "pointSizeScaleFactor", 1.0).clamp(1.0, MAX_STROKE),
        attenuation,
        // A minimum above the maximum (POINT_SIZE_MIN_EXCEEDS_MAX) gives way to it.
        min: min.min(max),
        max,
        ..Stroke::default()
    }
}

/// Material, PhysicalMaterial and UnlitMaterial, by name: an X3D 3.x document's Material
/// is no X3DOneSidedMaterialNode (X3D 4 added the type), yet browsers draw the X3D 4
/// texture fields it is given (FIELD_NOT_IN_VERSION reports them).
fn is_one_sided(doc: &crate::model::Document, material: NodeId) -> bool {
    doc.node(material).is_a("X3DOneSidedMaterialNode")
        || matches!(
            doc.node(material).type_name(),
            "Material" | "PhysicalMaterial" | "UnlitMaterial"
        )
}

/// The xxxTextureMapping of a material's xxxTexture field.
fn mapping(doc: &crate::model::Document, material: NodeId, texture_field: &str) -> String {
    doc.string_of(material, &format!("{texture_field}Mapping"))
        .unwrap_or_default()
}

/// Table 18.3.
fn stage_mode(text: &str) -> Option<StageMode> {
    Some(match text {
        "MODULATE" => StageMode::Modulate,
        // Replace the current colour with the texture (Arg1): the table's "Arg2"
        // contradicts its own description and the example under it ("MODULATE",
        // "REPLACE" gives Arg1.alpha).
        "REPLACE" => StageMode::Replace,
        "MODULATE2X" => StageMode::Modulate2x,
        "MODULATE4X" => StageMode::Modulate4x,
        "ADD" => StageMode::Add,
        "ADDSIGNED" => StageMode::AddSigned,
        "ADDSIGNED2X" => StageMode::AddSigned2x,
        "SUBTRACT" => StageMode::Subtract,
        "ADDSMOOTH" => StageMode::AddSmooth,
        "BLENDDIFFUSEALPHA" => StageMode::BlendDiffuseAlpha,
        "BLENDTEXTUREALPHA" => StageMode::BlendTextureAlpha,
        "BLENDFACTORALPHA" => StageMode::BlendFactorAlpha,
        "BLENDCURRENTALPHA" => StageMode::BlendCurrentAlpha,
        "MODULATEALPHA_ADDCOLOR" => StageMode::ModulateAlphaAddColor,
        "MODULATEINVALPHA_ADDCOLOR" => StageMode::ModulateInvAlphaAddColor,
        "MODULATEINVCOLOR_ADDALPHA" => StageMode::ModulateInvColorAddAlpha,
        "OFF" => StageMode::Off,
        "SELECTARG1" => StageMode::SelectArg1,
        "SELECTARG2" => StageMode::SelectArg2,
        "DOTPRODUCT3" => StageMode::DotProduct3,
        _ => return None,
    })
}

pub fn default_unlit() -> Material {
    Material {
        model: LightingModel::Unlit,
        diffuse: [1.0; 3],
        emissive: [1.0; 3],
        specular: [0.0; 3],
        ambient_intensity: 0.0,
        shininess: 0.0,
        metallic: 0.0,
        roughness: 1.0,
        alpha: 1.0,
        normal_scale: 1.0,
        occlusion_strength: 1.0,
        texture_replaces_rgb: false,
        ambient_of_diffuse_factor: false,
    }
}

pub fn unlit_from(m: Material) -> Material {
    Material {
        model: LightingModel::Unlit,
        ..m
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_mode_of_table_18_3_is_known() {
        for mode in [
            "MODULATE",
            "REPLACE",
            "MODULATE2X",
            "MODULATE4X",
            "ADD",
            "ADDSIGNED",
            "ADDSIGNED2X",
            "SUBTRACT",
            "ADDSMOOTH",
            "BLENDDIFFUSEALPHA",
            "BLENDTEXTUREALPHA",
            "BLENDFACTORALPHA",
            "BLENDCURRENTALPHA",
            "MODULATEALPHA_ADDCOLOR",
            "MODULATEINVALPHA_ADDCOLOR",
            "MODULATEINVCOLOR_ADDALPHA",
            "OFF",
            "SELECTARG1",
            "SELECTARG2",
            "DOTPRODUCT3",
        ] {
            assert!(stage_mode(mode).is_some(), "{mode}");
        }
        assert_eq!(stage_mode("modulate"), None);
    }
}
