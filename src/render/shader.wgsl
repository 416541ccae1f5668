// The shading of 19775-1 clause 17 (17.2.2) and the texturing of clause 18, over the
// lighting equations of `lighting.wgsl` (which this file follows when compiled).
// Positions are relative to the eye, in world orientation: V = normalize(-p).
//
// Two shadings share the equations: Phong shading (`vs_main` + `fs_phong`, per fragment,
// every material texture) and Gouraud shading (`vs_gouraud` + `fs_gouraud`, per vertex,
// with the main texture applied per fragment as 17.2.2.8 recommends).
//
// Colour spaces: the physical model computes in linear light, as the glTF 2.0 model it
// follows (17.2.2.6) does: its colours (baseColor, emissiveColor, Color nodes) are linear
// values, its colour textures (the main and the emissive texture) are decoded from sRGB,
// the Fog colour too, and the result is encoded to sRGB. Phong and unlit shading use the
// stored values as they are, with no conversion, as X_ITE draws them by default (its
// ColorSpace LINEAR_WHEN_PHYSICAL_MATERIAL: linear only for PhysicalMaterial); the
// view3dscene figures of issue 15 agree.

struct Globals {
    view_projection: mat4x4<f32>,
    // Clip space to background directions (the Background's axes, eye at the origin).
    background_from_clip: mat4x4<f32>,
    // World axes to camera axes (the rotation of the view).
    camera_from_world: mat4x4<f32>,
    environment: vec4<u32>,        // the panorama's texels are linear (HDR): 1
    viewport: vec4<f32>,           // the layer's width and height in target pixels, supersampling scale, background transparency
    forward_near: vec4<f32>,       // unit view direction, near plane distance
    fog_color_range: vec4<f32>,    // rgb, visibilityRange
    counts: vec4<u32>,             // fog (0 none, 1 linear, 2 exponential), lights, sky, ground
    sky: array<vec4<f32>, 8>,      // rgb, angle from the zenith
    ground: array<vec4<f32>, 8>,   // rgb, angle from the nadir
    lights: array<Light, 16>,
    env_sh: array<vec4<f32>, 9>,         // EnvironmentLight irradiance, L2 spherical harmonics
    env_from_world: array<vec4<f32>, 3>, // columns: world axes to the environment's
    env_info: vec4<u32>,                 // ENV_ bits, prefiltered mip levels
};

struct Material {
    diffuse_alpha: vec4<f32>,      // diffuse/base colour, 1 - transparency
    emissive_model: vec4<f32>,     // emissive colour, model (0 unlit, 1 Phong, 2 physical)
    specular_shininess: vec4<f32>, // specular colour, shininess × 128
    params: vec4<f32>,             // ambientIntensity, metallic, roughness, normalScale
    extra: vec4<f32>,              // occlusionStrength, texture replaces rgb (3.x), ambient of the diffuse factor (3.x)
};

struct Draw {
    front: Material,
    back: Material,
    misc: vec4<u32>,               // light mask, colour mode (0 none, 1 RGB, 2 RGBA), roles, stages
    sets_main: vec4<u32>,          // texture coordinate set of stages 0-3
    sets_roles: vec4<u32>,         // ... of emissive, normal, occlusion, specular/metallicRoughness
    sets_more: vec4<u32>,          // ... of shininess, ambient; clip plane count
    factor: vec4<f32>,             // MultiTexture colour and alpha
    cutoff: vec4<f32>,             // alpha cutoff
    stroke: vec4<f32>,             // line width or point size (image pixels), min, max, points
    stroke_attenuation: vec4<f32>, // points: size / (a + b·r + c·r²); lines: linetype
    stages: array<vec4<u32>, 4>,   // mode, alpha mode, source, function
    clip_planes: array<vec4<f32>, 4>,
};

// Roles present (bits of draw.misc.z).
const ROLE_EMISSIVE: u32 = 1u;
const ROLE_NORMAL: u32 = 2u;
const ROLE_OCCLUSION: u32 = 4u;
const ROLE_SPECULAR_OR_MR: u32 = 8u;
const ROLE_SHININESS: u32 = 16u;
const ROLE_AMBIENT: u32 = 32u;

// Read-only storage buffers on most devices: `Parameters` in `gpu/pipelines.rs` says why.
@group(0) @binding(0) var<uniform> globals: Globals;
@group(0) @binding(1) var t_env_specular: texture_cube<f32>;
@group(0) @binding(2) var t_env_diffuse: texture_cube<f32>;
@group(0) @binding(3) var t_brdf: texture_2d<f32>;
@group(0) @binding(4) var s_env: sampler;
@group(1) @binding(0) var<uniform> draw: Draw;
// The Background's panorama (transparent where it has none).
@group(0) @binding(5) var t_panorama: texture_cube<f32>;
@group(0) @binding(6) var s_panorama: sampler;
@group(2) @binding(0) var t_stage0: texture_2d<f32>;
@group(2) @binding(1) var t_stage1: texture_2d<f32>;
@group(2) @binding(2) var t_stage2: texture_2d<f32>;
@group(2) @binding(3) var t_stage3: texture_2d<f32>;
@group(2) @binding(4) var t_emissive: texture_2d<f32>;
@group(2) @binding(5) var t_normal: texture_2d<f32>;
@group(2) @binding(6) var t_occlusion: texture_2d<f32>;
@group(2) @binding(7) var t_specular_mr: texture_2d<f32>;
@group(2) @binding(8) var t_shininess: texture_2d<f32>;
@group(2) @binding(9) var t_ambient: texture_2d<f32>;
@group(2) @binding(10) var s_stage0: sampler;
@group(2) @binding(11) var s_stage1: sampler;
@group(2) @binding(12) var s_stage2: sampler;
@group(2) @binding(13) var s_stage3: sampler;
@group(2) @binding(14) var s_emissive: sampler;
@group(2) @binding(15) var s_normal: sampler;
@group(2) @binding(16) var s_occlusion: sampler;
@group(2) @binding(17) var s_specular_mr: sampler;
@group(2) @binding(18) var s_shininess: sampler;
@group(2) @binding(19) var s_ambient: sampler;
// A cube map texture of the first stage (clause 34), when draw.sets_more.w says so.
@group(2) @binding(20) var t_cube: texture_cube<f32>;
@group(2) @binding(21) var s_cube: sampler;

struct VertexIn {
    @location(0) position: vec3<f32>,
    @location(1) normal: vec3<f32>,
    @location(2) color: vec4<f32>,
    @location(3) tangent: vec4<f32>,
    @location(4) uv0: vec2<f32>,
    @location(5) uv1: vec2<f32>,
    @location(6) uv2: vec2<f32>,
    @location(7) uv3: vec2<f32>,
};

struct VertexOut {
    @builtin(position) clip: vec4<f32>,
    @location(0) position: vec3<f32>,
    @location(1) normal: vec3<f32>,
    @location(2) color: vec4<f32>,
    @location(3) tangent: vec4<f32>,
    @location(4) uv01: vec4<f32>,
    @location(5) uv23: vec4<f32>,
    // Gouraud shading: the lit colours of the front and the back side.
    @location(6) lit_front: vec4<f32>,
    @location(7) lit_back: vec4<f32>,
    // Lines: image pixels along the polyline, for its linetype pattern (linear on screen).
    @location(8) @interpolate(linear) along_line: f32,
};

// X3D t runs up the image, texture rows run down.
fn flip(uv: vec2<f32>) -> vec2<f32> {
    return vec2<f32>(uv.x, 1.0 - uv.y);
}

fn common_vertex(v: VertexIn) -> VertexOut {
    var out: VertexOut;
    out.clip = globals.view_projection * vec4<f32>(v.position, 1.0);
    out.position = v.position;
    out.normal = v.normal;
    out.color = v.color;
    out.tangent = v.tangent;
    out.uv01 = vec4<f32>(flip(v.uv0), flip(v.uv1));
    out.uv23 = vec4<f32>(flip(v.uv2), flip(v.uv3));
    return out;
}

@vertex
fn vs_main(v: VertexIn) -> VertexOut {
    return common_vertex(v);
}

// Lines and points as screen-aligned quads (WebGPU rasterizes lines and points one pixel
// wide only): one instance per segment (a, b) or point (a = b), six corners each.
struct StrokeIn {
    @builtin(vertex_index) corner: u32,
    // xyz, and the length of the polyline up to the end.
    @location(0) a: vec4<f32>,
    @location(1) b: vec4<f32>,
    @location(2) color_a: vec4<f32>,
    @location(3) color_b: vec4<f32>,
};

@vertex
fn vs_stroke(v: StrokeIn) -> VertexOut {
    var out: VertexOut;
    // Two triangles over (end, side): (0,-1) (1,-1) (1,1), (0,-1) (1,1) (0,1).
    let ends = array<f32, 6>(0.0, 1.0, 1.0, 0.0, 1.0, 0.0);
    let sides = array<f32, 6>(-1.0, -1.0, 1.0, -1.0, 1.0, 1.0);
    let end = ends[v.corner % 6u];
    let side = sides[v.corner % 6u];
    // Cut the segment at the near plane, so that both ends project.
    let near = globals.forward_near.w;
    var pa = v.a.xyz;
    var pb = v.b.xyz;
    let da = dot(pa, globals.forward_near.xyz);
    let db = dot(pb, globals.forward_near.xyz);
    if da < near && db < near {
        out.clip = vec4<f32>(2.0, 2.0, 2.0, 1.0);
        return out;
    }
    if da < near {
        pa = mix(pa, pb, (near - da) / (db - da));
    } else if db < near {
        pb = mix(pb, pa, (near - db) / (da - db));
    }
    let ca = globals.view_projection * vec4<f32>(pa, 1.0);
    let cb = globals.view_projection * vec4<f32>(pb, 1.0);
    let half_pixels = globals.viewport.xy * 0.5;
    let sa = ca.xy / ca.w * half_pixels;
    let sb = cb.xy / cb.w * half_pixels;
    let points = draw.stroke.w != 0.0;
    var size = draw.stroke.x;
    let p = select(pa, pb, end > 0.5);
    if points {
        let r = length(p);
        let att = draw.stroke_attenuation.xyz;
        size = clamp(size / max(att.x + att.y * r + att.z * r * r, 1e-30), draw.stroke.y, draw.stroke.z);
    }
    let half_width = 0.5 * size * globals.viewport.z;
    var along = sb - sa;
    along = select(vec2<f32>(1.0, 0.0), normalize(along), dot(along, along) > 0.0);
    let across = vec2<f32>(-along.y, along.x);
    // Points are squares: they also reach half a size along.
    let offset = across * side * half_width + along * select(0.0, (end * 2.0 - 1.0) * half_width, points);
    var clip = select(ca, cb, end > 0.5);
    clip = vec4<f32>(clip.xy + offset / half_pixels * clip.w, clip.zw);
    out.clip = clip;
    out.position = p;
    // The pattern runs on from the polyline's length at a, in this segment's pixels per
    // unit (so it bends with the polyline; the scale changes from segment to segment only
    // with depth).
    let pixels_per_unit = length(sb - sa) / globals.viewport.z / max(distance(pa, pb), 1e-30);
    out.along_line = (v.a.w + distance(v.a.xyz, p)) * pixels_per_unit;
    out.color = select(v.color_a, v.color_b, end > 0.5);
    out.lit_front = material_color(draw.front, out.color);
    out.lit_back = out.lit_front;
    return out;
}

// Whether a line's pixel `along` its polyline (in units of its width) is drawn by its
// linetype (12.4.3 Table 12.3; the lengths are the browser's): 2 dashed, 3 dotted,
// 4 dash-dotted, 5 dash-dot-dot, repeating every 16; anything else solid.
fn on_linetype(linetype: u32, along: f32) -> bool {
    let p = along - 16.0 * floor(along / 16.0);
    switch linetype {
        case 2u: { return p < 9.0; }
        case 3u: { return p - 4.0 * floor(p / 4.0) < 2.0; }
        case 4u: { return p < 8.0 || (p >= 11.0 && p < 13.0); }
        case 5u: { return p < 6.0 || (p >= 8.0 && p < 10.0) || (p >= 12.0 && p < 14.0); }
        default: { return true; }
    }
}

fn phong(s: Surface, p: vec3<f32>, n: vec3<f32>, v: vec3<f32>) -> vec3<f32> {
    var sum = vec3<f32>(0.0);
    for (var i = 0u; i < globals.counts.y; i = i + 1u) {
        if (draw.misc.x & (1u << i)) != 0u {
            sum = sum + light_phong(globals.lights[i], s, p, n, v);
        }
    }
    return s.emissive + s.occlusion * min(sum, vec3<f32>(MAX_RADIANCE));
}

// What the EnvironmentLight has (bits of env_info.x; `gpu/environment.rs`).
const ENV_SH: u32 = 1u;
const ENV_SPECULAR: u32 = 2u;
const ENV_DIFFUSE: u32 = 4u;

fn env_direction(d: vec3<f32>) -> vec3<f32> {
    let m = globals.env_from_world;
    return m[0].xyz * d.x + m[1].xyz * d.y + m[2].xyz * d.z;
}

// The irradiance E(n) of the diffuseCoefficients over π: the light a white Lambertian
// surface facing n reflects. The coefficients are of the irradiance (glTF's
// irradianceCoefficients), on the real L2 basis of Ramamoorthi and Hanrahan (2001), in
// the order L00, L1−1, L10, L11, L2−2, L2−1, L20, L21, L22.
fn sh_irradiance(n: vec3<f32>) -> vec3<f32> {
    let c = globals.env_sh;
    let e = c[0].rgb * 0.282095
        + c[1].rgb * (0.488603 * n.y)
        + c[2].rgb * (0.488603 * n.z)
        + c[3].rgb * (0.488603 * n.x)
        + c[4].rgb * (1.092548 * n.x * n.y)
        + c[5].rgb * (1.092548 * n.y * n.z)
        + c[6].rgb * (0.315392 * (3.0 * n.z * n.z - 1.0))
        + c[7].rgb * (1.092548 * n.x * n.z)
        + c[8].rgb * (0.546274 * (n.x * n.x - n.y * n.y));
    return max(e, vec3<f32>(0.0)) / PI;
}

// The diffuse light along the world normal n: the irradiance map, else the coefficients.
fn env_diffuse(n: vec3<f32>) -> vec3<f32> {
    let flags = globals.env_info.x;
    let d = env_direction(n);
    if (flags & ENV_DIFFUSE) != 0u {
        return textureSampleLevel(t_env_diffuse, s_env, d, 0.0).rgb;
    }
    if (flags & ENV_SH) != 0u {
        return sh_irradiance(d);
    }
    return vec3<f32>(0.0);
}

// The radiance along the world reflection r prefiltered for `roughness`. Without a
// specularTexture the irradiance (the diffuseTexture's, else the coefficients') stands
// in: the environment as blurred as roughness 1 blurs it (darker and duller than a real
// reflection at low roughness).
fn env_specular(r: vec3<f32>, roughness: f32) -> vec3<f32> {
    let flags = globals.env_info.x;
    let d = env_direction(r);
    if (flags & ENV_SPECULAR) != 0u {
        let lod = roughness * f32(max(globals.env_info.y, 1u) - 1u);
        return textureSampleLevel(t_env_specular, s_env, d, lod).rgb;
    }
    if (flags & ENV_DIFFUSE) != 0u {
        return textureSampleLevel(t_env_diffuse, s_env, d, 0.0).rgb;
    }
    if (flags & ENV_SH) != 0u {
        return sh_irradiance(d);
    }
    return vec3<f32>(0.0);
}

// An EnvironmentLight's image-based light on a PhysicalMaterial, as the glTF Sample
// Viewer computes it (split sum): specular = prefiltered radiance × (F × A + B) with the
// BRDF table's A and B at (n·v, roughness) and a Fresnel term raised for rough surfaces,
// plus the light scattered more than once between the microfacets, which a
// single-scattering BRDF loses (Fdez-Agüera 2019, as the Sample Viewer and X_ITE add it:
// rough metals keep their brightness); diffuse = irradiance × c_diff × what the specular
// lobe leaves; times the light's colour and intensity.
fn environment_physical(light: Light, s: Surface, n: vec3<f32>, v: vec3<f32>) -> vec3<f32> {
    let metallic = clamp(s.metallic, 0.0, 1.0);
    let roughness = clamp(s.roughness, 0.0, 1.0);
    let c_diff = mix(s.diffuse, vec3<f32>(0.0), metallic);
    let f0 = mix(vec3<f32>(0.04), s.diffuse, metallic);
    let n_dot_v = clamp(dot(n, v), 0.0, 1.0);
    let brdf = textureSampleLevel(t_brdf, s_env, vec2<f32>(n_dot_v, roughness), 0.0).rg;
    let fresnel = f0 + (max(vec3<f32>(1.0 - roughness), f0) - f0) * pow(1.0 - n_dot_v, 5.0);
    let single = fresnel * brdf.x + brdf.y;
    // The energy the single scattering misses, returned with the average Fresnel.
    let missed = 1.0 - (brdf.x + brdf.y);
    let f_average = f0 + (1.0 - f0) / 21.0;
    let multiple = single * missed * f_average / (1.0 - f_average * missed);
    let reflected = single + multiple;
    let specular = env_specular(reflect(-v, n), roughness) * reflected;
    // What the specular lobe reflects does not reach the diffuse one (the direct lights'
    // (1 − F), here the lobe's integral).
    let diffuse = env_diffuse(n) * c_diff * max(vec3<f32>(1.0) - reflected, vec3<f32>(0.0));
    let radiance = light.color_intensity.rgb * light.color_intensity.w * (diffuse + specular);
    return min(radiance, vec3<f32>(MAX_RADIANCE));
}

fn physical(s: Surface, p: vec3<f32>, n: vec3<f32>, v: vec3<f32>) -> vec3<f32> {
    var sum = vec3<f32>(0.0);
    for (var i = 0u; i < globals.counts.y; i = i + 1u) {
        if (draw.misc.x & (1u << i)) != 0u {
            let light = globals.lights[i];
            if u32(light.location_kind.w) == 3u {
                sum = sum + environment_physical(light, s, n, v);
            } else {
                sum = sum + light_physical(light, s, p, n, v);
            }
        }
    }
    return s.emissive + s.occlusion * min(sum, vec3<f32>(MAX_RADIANCE));
}

// The material's colour before textures: diffuseParameter (Phong), baseParameter
// (physical) or emissiveParameter (unlit), with applyColorPerVertex.
fn material_color(m: Material, vertex_color: vec4<f32>) -> vec4<f32> {
    let unlit = u32(m.emissive_model.w) == 0u;
    var color = vec4<f32>(select(m.diffuse_alpha.rgb, m.emissive_model.rgb, unlit), m.diffuse_alpha.a);
    if draw.misc.y == 1u {
        color = vec4<f32>(vertex_color.rgb, color.a);
    } else if draw.misc.y == 2u {
        color = vertex_color;
    }
    return color;
}

// The surface without textures (Gouraud shading, and the base of Phong shading).
fn plain_surface(m: Material, color: vec3<f32>) -> Surface {
    var s: Surface;
    s.diffuse = color;
    s.emissive = m.emissive_model.rgb;
    s.specular = m.specular_shininess.rgb;
    s.shininess = m.specular_shininess.w;
    // ambientParameter. X3D 4 (17.2.2.5): ambientIntensity × diffuseColor ×
    // textureSample(ambientTexture).rgb: the Material's own diffuseColor, neither the main
    // texture nor a Color node (the ambient texture, multiplied in by `fs_phong`, is the
    // ambient term's own texture). X3D 3.x (3.3's ambient_i = Iia × ODrgb × Oa): the
    // diffuse factor ODrgb of Table 17.3, main texture and Color node included.
    s.ambient = m.params.x * select(m.diffuse_alpha.rgb, color, m.extra.z != 0.0);
    s.metallic = m.params.y;
    s.roughness = m.params.z;
    s.occlusion = 1.0;
    return s;
}

fn shade(m: Material, s: Surface, p: vec3<f32>, n: vec3<f32>) -> vec3<f32> {
    let model = u32(m.emissive_model.w);
    if model == 0u {
        return s.diffuse;
    }
    let v = select(vec3<f32>(0.0, 0.0, 1.0), normalize(-p), length(p) > 0.0);
    if model == 1u {
        return phong(s, p, n, v);
    }
    return physical(s, p, n, v);
}

// The colour Gouraud shading lights: the material colour, or white where an X3D 3.x
// texture replaces it (the fragment multiplies by the texture).
fn gouraud_color(m: Material, vertex_color: vec4<f32>) -> vec4<f32> {
    let color = material_color(m, vertex_color);
    if draw.misc.w > 0u && m.extra.y != 0.0 {
        return vec4<f32>(1.0, 1.0, 1.0, color.a);
    }
    return color;
}

@vertex
fn vs_gouraud(v: VertexIn) -> VertexOut {
    var out = common_vertex(v);
    let n = unit_or_zero(v.normal);
    let front = gouraud_color(draw.front, v.color);
    let back = gouraud_color(draw.back, v.color);
    out.lit_front = vec4<f32>(shade(draw.front, plain_surface(draw.front, front.rgb), v.position, n), front.a);
    out.lit_back = vec4<f32>(shade(draw.back, plain_surface(draw.back, back.rgb), v.position, -n), back.a);
    return out;
}

fn uv_of(index: u32, in: VertexOut) -> vec2<f32> {
    switch index {
        case 1u: { return in.uv01.zw; }
        case 2u: { return in.uv23.xy; }
        case 3u: { return in.uv23.zw; }
        default: { return in.uv01.xy; }
    }
}

// The main texture's stages sampled (white where absent). Draw-level conditions only, so
// that sampling stays in uniform control flow.
struct StageSamples {
    s: array<vec4<f32>, 4>,
};

fn sample_stages(in: VertexOut) -> StageSamples {
    var out: StageSamples;
    let count = draw.misc.w;
    out.s[0] = vec4<f32>(1.0);
    out.s[1] = vec4<f32>(1.0);
    out.s[2] = vec4<f32>(1.0);
    out.s[3] = vec4<f32>(1.0);
    let cube = draw.sets_more.w & 3u;
    if count > 0u && cube == 0u {
        out.s[0] = textureSample(t_stage0, s_stage0, uv_of(draw.sets_main.x, in));
    }
    if count > 0u && cube != 0u {
        out.s[0] = sample_cube(cube, in);
    }
    if count > 1u {
        out.s[1] = textureSample(t_stage1, s_stage1, uv_of(draw.sets_main.y, in));
    }
    if count > 2u {
        out.s[2] = textureSample(t_stage2, s_stage2, uv_of(draw.sets_main.z, in));
    }
    if count > 3u {
        out.s[3] = textureSample(t_stage3, s_stage3, uv_of(draw.sets_main.w, in));
    }
    return out;
}

// A cube map texture (34.2: the texture coordinates are a direction): by draw.sets_more.w,
// 1 the view vector reflected about the normal in world axes, 2 the same in camera axes
// (CAMERASPACEREFLECTIONVECTOR), 3 the camera-space normal (CAMERASPACENORMAL); bit 2:
// the texels are linear (HDR), encoded to sRGB as the other textures' stored values are.
fn sample_cube(lookup: u32, in: VertexOut) -> vec4<f32> {
    let n = unit_or_zero(in.normal);
    let view = select(vec3<f32>(0.0, 0.0, -1.0), normalize(in.position), length(in.position) > 0.0);
    var direction = reflect(view, n);
    if lookup == 3u {
        direction = n;
    }
    if lookup >= 2u {
        direction = (globals.camera_from_world * vec4<f32>(direction, 0.0)).xyz;
    }
    let texel = textureSample(t_cube, s_cube, direction);
    if (draw.sets_more.w & 4u) != 0u {
        return vec4<f32>(linear_to_srgb(clamp(texel.rgb, vec3<f32>(0.0), vec3<f32>(1.0))), texel.a);
    }
    return texel;
}

// One MultiTexture stage (18.4.3): Arg1 the texture, Arg2 from the source.
fn stage_mode(mode: u32, a1: vec4<f32>, a2: vec4<f32>, diffuse_alpha: f32) -> vec4<f32> {
    let factor = draw.factor;
    switch mode {
        case 1u: { return a1; }                                          // REPLACE
        case 2u: { return a1 * a2 * 2.0; }                               // MODULATE2X
        case 3u: { return a1 * a2 * 4.0; }                               // MODULATE4X
        case 4u: { return a1 + a2; }                                     // ADD
        case 5u: { return a1 + a2 - vec4<f32>(0.5); }                    // ADDSIGNED
        case 6u: { return (a1 + a2 - vec4<f32>(0.5)) * 2.0; }            // ADDSIGNED2X
        case 7u: { return a1 - a2; }                                     // SUBTRACT
        case 8u: { return a1 + a2 - a1 * a2; }                           // ADDSMOOTH
        case 9u: { return mix(a2, a1, diffuse_alpha); }                  // BLENDDIFFUSEALPHA
        case 10u: { return mix(a2, a1, a1.a); }                          // BLENDTEXTUREALPHA
        case 11u: { return mix(a2, a1, factor.a); }                      // BLENDFACTORALPHA
        case 12u: { return mix(a2, a1, a2.a); }                          // BLENDCURRENTALPHA
        case 13u: { return vec4<f32>(a1.rgb + a1.a * a2.rgb, a1.a); }    // MODULATEALPHA_ADDCOLOR
        case 14u: { return vec4<f32>((1.0 - a1.a) * a2.rgb + a1.rgb, a1.a); } // MODULATEINVALPHA_ADDCOLOR
        case 15u: { return vec4<f32>((vec3<f32>(1.0) - a1.rgb) * a2.rgb + vec3<f32>(a1.a), a1.a); } // MODULATEINVCOLOR_ADDALPHA
        case 16u: { return a2; }                                         // OFF: see mix_texture
        case 17u: { return a1; }                                         // SELECTARG1
        case 18u: { return a2; }                                         // SELECTARG2
        case 19u: {                                                      // DOTPRODUCT3
            let d = dot(a1.rgb * 2.0 - vec3<f32>(1.0), a2.rgb * 2.0 - vec3<f32>(1.0));
            return vec4<f32>(d);
        }
        default: { return a1 * a2; }                                     // MODULATE
    }
}

// mixTexture (17.2.2.3): the main texture applied to `color`. `specular` is the specular
// colour (the SPECULAR source).
// X3D 3.x lets a single RGB(A) texture replace the colour; Gouraud shading (`lit`) has
// lit with white instead and multiplies. Such a texture also sets aside the Color or
// ColorRGBA node (11.4.2, 11.4.3: "RGB or RGBA textures take precedence over colours"),
// so its alpha modulates the material's 1 − transparency (17.2.2.3: "The Material's
// transparency field modulates the alpha in the texture"; A = AT in Table 17.3 is the
// transparency 0 case).
fn mix_texture(color: vec4<f32>, specular: vec3<f32>, m: Material, samples: StageSamples, lit: bool) -> vec4<f32> {
    let count = draw.misc.w;
    if count == 0u {
        return color;
    }
    if count == 1u && draw.stages[0].x == 0u && draw.stages[0].z == 0u && draw.stages[0].w == 0u {
        let t = samples.s[0];
        let replaces = m.extra.y != 0.0;
        let rgb = select(color.rgb * t.rgb, t.rgb, replaces && !lit);
        let a = select(color.a, m.diffuse_alpha.a, replaces) * t.a;
        return vec4<f32>(rgb, a);
    }
    var current = color;
    for (var i = 0u; i < count; i = i + 1u) {
        let stage = draw.stages[i];
        var a1 = samples.s[i];
        var a2 = current;
        switch stage.z {
            case 1u: { a2 = color; }
            case 2u: { a2 = vec4<f32>(specular, 1.0); }
            case 3u: { a2 = draw.factor; }
            default: {}
        }
        if stage.w == 1u {
            a1 = vec4<f32>(1.0) - a1;
        } else if stage.w == 2u {
            a1 = vec4<f32>(a1.a);
        }
        // OFF turns the stage off: the previous stage's result passes on, whatever
        // the stage's source names.
        let rgb = select(stage_mode(stage.x, a1, a2, color.a), current, stage.x == 16u);
        let alpha = select(stage_mode(stage.y, a1, a2, color.a), current, stage.y == 16u);
        current = clamp(vec4<f32>(rgb.rgb, alpha.a), vec4<f32>(0.0), vec4<f32>(1.0));
    }
    return current;
}

// Clip planes (a ClipPlane's plane): what lies on the negative side is cut.
fn clip(p: vec3<f32>) {
    for (var i = 0u; i < draw.sets_more.z; i = i + 1u) {
        let plane = draw.clip_planes[i];
        if dot(plane.xyz, p) + plane.w < 0.0 {
            discard;
        }
    }
}

fn is_physical(m: Material) -> bool {
    return u32(m.emissive_model.w) == 2u;
}

// The main texture's samples in linear light (the physical model's colour textures).
fn decoded_stages(samples: StageSamples) -> StageSamples {
    var out: StageSamples;
    for (var i = 0u; i < 4u; i = i + 1u) {
        out.s[i] = vec4<f32>(srgb_to_linear(samples.s[i].rgb), samples.s[i].a);
    }
    return out;
}

// Fog, then the output value: `rgb` is linear light for the physical model (the fog
// colour is decoded to blend with it, so that a fully fogged shape has the Fog's colour
// as every other shape does), stored values otherwise.
fn finish(rgb: vec3<f32>, alpha: f32, p: vec3<f32>, linear: bool) -> vec4<f32> {
    var fog = globals.fog_color_range.rgb;
    if linear {
        fog = srgb_to_linear(fog);
    }
    let f = fog_interpolant(globals.counts.x, globals.fog_color_range.w, length(p));
    var out = clamp(mix(fog, rgb, f), vec3<f32>(0.0), vec3<f32>(1.0));
    if linear {
        out = linear_to_srgb(out);
    }
    return vec4<f32>(out, clamp(alpha, 0.0, 1.0));
}

@fragment
fn fs_phong(in: VertexOut, @builtin(front_facing) front_facing: bool) -> @location(0) vec4<f32> {
    // Every sample first, in uniform control flow (facing and clipping are not uniform).
    let samples = sample_stages(in);
    let roles = draw.misc.z;
    var emissive_t = vec4<f32>(1.0);
    var normal_t = vec4<f32>(0.5, 0.5, 1.0, 1.0);
    var occlusion_t = vec4<f32>(1.0);
    var specular_mr_t = vec4<f32>(1.0);
    var shininess_t = vec4<f32>(1.0);
    var ambient_t = vec4<f32>(1.0);
    if (roles & ROLE_EMISSIVE) != 0u {
        emissive_t = textureSample(t_emissive, s_emissive, uv_of(draw.sets_roles.x, in));
    }
    if (roles & ROLE_NORMAL) != 0u {
        normal_t = textureSample(t_normal, s_normal, uv_of(draw.sets_roles.y, in));
    }
    if (roles & ROLE_OCCLUSION) != 0u {
        occlusion_t = textureSample(t_occlusion, s_occlusion, uv_of(draw.sets_roles.z, in));
    }
    if (roles & ROLE_SPECULAR_OR_MR) != 0u {
        specular_mr_t = textureSample(t_specular_mr, s_specular_mr, uv_of(draw.sets_roles.w, in));
    }
    if (roles & ROLE_SHININESS) != 0u {
        shininess_t = textureSample(t_shininess, s_shininess, uv_of(draw.sets_more.x, in));
    }
    if (roles & ROLE_AMBIENT) != 0u {
        ambient_t = textureSample(t_ambient, s_ambient, uv_of(draw.sets_more.y, in));
    }
    clip(in.position);
    // Surfaces and points have linetype 1 (solid).
    if !on_linetype(u32(draw.stroke_attenuation.w), in.along_line / draw.stroke.x) {
        discard;
    }

    var m = draw.front;
    if !front_facing {
        m = draw.back;
    }
    let linear = is_physical(m);
    var stages = samples;
    if linear {
        stages = decoded_stages(samples);
        emissive_t = vec4<f32>(srgb_to_linear(emissive_t.rgb), emissive_t.a);
    }
    let color = mix_texture(material_color(m, in.color), m.specular_shininess.rgb, m, stages, false);
    if color.a < draw.cutoff.x {
        discard;
    }
    let model = u32(m.emissive_model.w);
    if model == 0u {
        // Unlit: the emissiveTexture (if any) is the main texture; nothing else applies.
        return finish(color.rgb, color.a, in.position, false);
    }
    // The normal, perturbed by the normal texture in tangent space (12.3.4), then turned
    // to the side seen.
    var n = unit_or_zero(in.normal);
    if (roles & ROLE_NORMAL) != 0u && length(in.tangent.xyz) > 0.0 && length(n) > 0.0 {
        let t = unit_or_zero(in.tangent.xyz - n * dot(n, in.tangent.xyz));
        let b = cross(n, t) * in.tangent.w;
        let scale = m.params.w;
        let local = unit_or_zero((normal_t.rgb * 2.0 - vec3<f32>(1.0)) * vec3<f32>(scale, scale, 1.0));
        n = unit_or_zero(t * local.x + b * local.y + n * local.z);
    }
    if !front_facing {
        n = -n;
    }
    var s = plain_surface(m, color.rgb);
    s.emissive = m.emissive_model.rgb * emissive_t.rgb;
    s.ambient = s.ambient * ambient_t.rgb;
    if model == 1u {
        s.specular = s.specular * specular_mr_t.rgb;
        s.shininess = s.shininess * shininess_t.a;
    } else {
        s.metallic = s.metallic * specular_mr_t.b;
        s.roughness = s.roughness * specular_mr_t.g;
    }
    s.occlusion = mix(1.0, occlusion_t.r, m.extra.x);
    return finish(shade(m, s, in.position, n), color.a, in.position, linear);
}

@fragment
fn fs_gouraud(in: VertexOut, @builtin(front_facing) front_facing: bool) -> @location(0) vec4<f32> {
    let samples = sample_stages(in);
    clip(in.position);
    var m = draw.front;
    var lit = in.lit_front;
    if !front_facing {
        m = draw.back;
        lit = in.lit_back;
    }
    // Lit per vertex in linear light for the physical model: its texture is decoded too.
    let linear = is_physical(m);
    var stages = samples;
    if linear {
        stages = decoded_stages(samples);
    }
    let color = mix_texture(lit, m.specular_shininess.rgb, m, stages, true);
    if color.a < draw.cutoff.x {
        discard;
    }
    return finish(color.rgb, color.a, in.position, linear);
}

// The Background: a triangle covering the screen, coloured by the direction of each
// pixel (24.4.1: sky colours by the angle from the zenith, ground colours by the angle
// from the nadir, interpolated, the ground over the sky up to its last angle; then the
// panorama cube over them).
struct BackgroundOut {
    @builtin(position) clip: vec4<f32>,
    @location(0) ndc: vec2<f32>,
};

@vertex
fn vs_background(@builtin(vertex_index) index: u32) -> BackgroundOut {
    var out: BackgroundOut;
    let xy = vec2<f32>(f32((index << 1u) & 2u), f32(index & 2u)) * 2.0 - vec2<f32>(1.0);
    out.clip = vec4<f32>(xy, 0.0, 1.0);
    out.ndc = xy;
    return out;
}

fn gradient_color(angle: f32, is_sky: bool) -> vec3<f32> {
    let count = select(globals.counts.w, globals.counts.z, is_sky);
    var entry = select(globals.ground[0], globals.sky[0], is_sky);
    var color = entry.rgb;
    for (var i = 1u; i < count; i = i + 1u) {
        let next = select(globals.ground[i], globals.sky[i], is_sky);
        if angle <= next.w {
            let span = next.w - entry.w;
            let t = select(1.0, (angle - entry.w) / span, span > 0.0);
            return mix(entry.rgb, next.rgb, clamp(t, 0.0, 1.0));
        }
        entry = next;
        color = next.rgb;
    }
    return color;
}

@fragment
fn fs_background(in: BackgroundOut) -> @location(0) vec4<f32> {
    // Reversed depth: the near plane is at depth 1, the far plane at 0.
    let near = globals.background_from_clip * vec4<f32>(in.ndc, 1.0, 1.0);
    let far = globals.background_from_clip * vec4<f32>(in.ndc, 0.0, 1.0);
    let direction = unit_or_zero(far.xyz / far.w - near.xyz / near.w);
    let from_zenith = acos(clamp(direction.y, -1.0, 1.0));
    var rgb = gradient_color(from_zenith, true);
    if globals.counts.w > 0u {
        let from_nadir = PI - from_zenith;
        let last = globals.ground[globals.counts.w - 1u].w;
        if from_nadir <= last || globals.counts.w == 1u && from_nadir <= PI / 2.0 {
            rgb = gradient_color(from_nadir, false);
        }
    }
    // The panorama in front of the sky and ground, which show where it is transparent
    // (24.4.1); a missing panorama is a transparent cube.
    var panorama = textureSample(t_panorama, s_panorama, direction);
    if globals.environment.x == 1u {
        panorama = vec4<f32>(linear_to_srgb(clamp(panorama.rgb, vec3<f32>(0.0), vec3<f32>(1.0))), panorama.a);
    }
    rgb = mix(rgb, panorama.rgb, panorama.a);
    return vec4<f32>(rgb, 1.0 - globals.viewport.w);
}
