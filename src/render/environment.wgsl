// The preparation of an EnvironmentLight's cube maps (`gpu/environment.rs`): each face of
// each mip level is drawn by a triangle covering it.
//
// `fs_prefilter`: the radiance prefiltered by the GGX distribution of one roughness, as the
// glTF Sample Viewer's (and its glTF-IBL-Sampler's) split-sum approximation does: N = V = R,
// GGX importance samples weighted by N·L, each read from the mip level whose texels match
// the sample's solid angle (filtered importance sampling, GPU Gems 3 ch. 20), so that few
// samples give no noise.
// `fs_irradiance`: the cosine-weighted irradiance over π (the light a white Lambertian
// surface facing that way reflects), from a low mip level of the radiance.

struct Pass {
    face_roughness: vec4<f32>, // face (0–5), roughness, target face size, source level-0 size
    levels: vec4<f32>,         // source mip levels
};

@group(0) @binding(0) var<uniform> pass_: Pass;
@group(0) @binding(1) var t_source: texture_cube<f32>;
@group(0) @binding(2) var s_source: sampler;

const PI_ENV: f32 = 3.14159265358979;
const SAMPLES: u32 = 64u;

@vertex
fn vs_face(@builtin(vertex_index) index: u32) -> @builtin(position) vec4<f32> {
    let xy = vec2<f32>(f32((index << 1u) & 2u), f32(index & 2u)) * 2.0 - vec2<f32>(1.0);
    return vec4<f32>(xy, 0.0, 1.0);
}

// The direction through `uv` (from the top left, in [0, 1]) of a WebGPU cube face (+X, −X,
// +Y, −Y, +Z, −Z: the Vulkan and Direct3D convention).
fn face_direction(face: u32, uv: vec2<f32>) -> vec3<f32> {
    let s = uv.x * 2.0 - 1.0;
    let t = uv.y * 2.0 - 1.0;
    switch face {
        case 0u: { return normalize(vec3<f32>(1.0, -t, -s)); }
        case 1u: { return normalize(vec3<f32>(-1.0, -t, s)); }
        case 2u: { return normalize(vec3<f32>(s, 1.0, t)); }
        case 3u: { return normalize(vec3<f32>(s, -1.0, -t)); }
        case 4u: { return normalize(vec3<f32>(s, -t, 1.0)); }
        default: { return normalize(vec3<f32>(-s, -t, -1.0)); }
    }
}

fn hammersley(i: u32, count: u32) -> vec2<f32> {
    return vec2<f32>(f32(i) / f32(count), f32(reverseBits(i)) * 2.3283064365386963e-10);
}

// A frame whose third axis is `n`.
fn basis(n: vec3<f32>) -> mat3x3<f32> {
    let up = select(vec3<f32>(1.0, 0.0, 0.0), vec3<f32>(0.0, 0.0, 1.0), abs(n.z) < 0.999);
    let t = normalize(cross(up, n));
    return mat3x3<f32>(t, cross(n, t), n);
}

fn direction_of(position: vec4<f32>) -> vec3<f32> {
    let face = u32(pass_.face_roughness.x);
    return face_direction(face, position.xy / pass_.face_roughness.z);
}

// The mip level of the source whose texels cover `solid_angle`.
fn level_for(solid_angle: f32) -> f32 {
    let size = pass_.face_roughness.w;
    let texel = 4.0 * PI_ENV / (6.0 * size * size);
    return clamp(0.5 * log2(solid_angle / texel) + 1.0, 0.0, pass_.levels.x - 1.0);
}

@fragment
fn fs_prefilter(@builtin(position) position: vec4<f32>) -> @location(0) vec4<f32> {
    let n = direction_of(position);
    let roughness = pass_.face_roughness.y;
    if roughness <= 0.0 {
        return vec4<f32>(textureSampleLevel(t_source, s_source, n, 0.0).rgb, 1.0);
    }
    let alpha = roughness * roughness;
    let frame = basis(n);
    var sum = vec3<f32>(0.0);
    var weight = 0.0;
    for (var i = 0u; i < SAMPLES; i = i + 1u) {
        let xi = hammersley(i, SAMPLES);
        // GGX half vector about n.
        let cos_h = sqrt((1.0 - xi.y) / (1.0 + (alpha * alpha - 1.0) * xi.y));
        let sin_h = sqrt(max(0.0, 1.0 - cos_h * cos_h));
        let phi = 2.0 * PI_ENV * xi.x;
        let h = frame * vec3<f32>(sin_h * cos(phi), sin_h * sin(phi), cos_h);
        let l = 2.0 * dot(n, h) * h - n;
        let n_dot_l = dot(n, l);
        if n_dot_l > 0.0 {
            // pdf of l: D(h) · (n·h) / (4 (v·h)), with v = n.
            let d_denominator = cos_h * cos_h * (alpha * alpha - 1.0) + 1.0;
            let d = alpha * alpha / (PI_ENV * d_denominator * d_denominator);
            let pdf = max(d / 4.0, 1e-6);
            let level = level_for(1.0 / (f32(SAMPLES) * pdf));
            sum = sum + textureSampleLevel(t_source, s_source, l, level).rgb * n_dot_l;
            weight = weight + n_dot_l;
        }
    }
    return vec4<f32>(sum / max(weight, 1e-6), 1.0);
}

@fragment
fn fs_irradiance(@builtin(position) position: vec4<f32>) -> @location(0) vec4<f32> {
    let n = direction_of(position);
    let frame = basis(n);
    var sum = vec3<f32>(0.0);
    let count = SAMPLES * 4u;
    for (var i = 0u; i < count; i = i + 1u) {
        let xi = hammersley(i, count);
        // Cosine-weighted: pdf = (n·l) / π, so the mean of the samples is E / π.
        let r = sqrt(xi.y);
        let phi = 2.0 * PI_ENV * xi.x;
        let l = frame * vec3<f32>(r * cos(phi), r * sin(phi), sqrt(max(0.0, 1.0 - xi.y)));
        let pdf = max(sqrt(max(0.0, 1.0 - xi.y)) / PI_ENV, 1e-6);
        let level = level_for(1.0 / (f32(count) * pdf));
        sum = sum + textureSampleLevel(t_source, s_source, l, level).rgb;
    }
    return vec4<f32>(sum / f32(count), 1.0);
}
