// The lighting equations of 19775-1 clause 17 (17.2.2), evaluated per fragment (Phong
// shading). Positions are relative to the eye, in world orientation: V = normalize(-p).

struct Light {
    color_intensity: vec4<f32>,    // rgb colour, intensity
    location_kind: vec4<f32>,      // xyz location, kind (0 directional, 1 point, 2 spot)
    direction_ambient: vec4<f32>,  // xyz unit direction of travel, ambientIntensity
    attenuation_radius: vec4<f32>, // c1, c2, c3, radius
    spot: vec4<f32>,               // beamWidth, cutOffAngle
};

struct Globals {
    view_projection: mat4x4<f32>,
    fog_color_range: vec4<f32>,    // rgb, visibilityRange
    counts: vec4<u32>,             // fog (0 none, 1 linear, 2 exponential), light count
    lights: array<Light, 16>,
};

struct Material {
    diffuse_alpha: vec4<f32>,      // diffuse/base colour, 1 - transparency
    emissive_model: vec4<f32>,     // emissive colour, model (0 unlit, 1 Phong, 2 physical)
    specular_shininess: vec4<f32>, // specular colour, shininess × 128
    params: vec4<f32>,             // ambientIntensity, metallic, roughness
    flags: vec4<u32>,              // has texture, texture replaces rgb, replaces alpha
};

struct Draw {
    front: Material,
    back: Material,
    misc: vec4<u32>,               // light mask, has per-vertex colour
    cutoff: vec4<f32>,             // alpha cutoff
};

@group(0) @binding(0) var<uniform> globals: Globals;
@group(1) @binding(0) var<uniform> draw: Draw;
@group(2) @binding(0) var base_texture: texture_2d<f32>;
@group(2) @binding(1) var base_sampler: sampler;

struct VertexIn {
    @location(0) position: vec3<f32>,
    @location(1) normal: vec3<f32>,
    @location(2) color: vec4<f32>,
    @location(3) tex_coord: vec2<f32>,
};

struct VertexOut {
    @builtin(position) clip: vec4<f32>,
    @location(0) position: vec3<f32>,
    @location(1) normal: vec3<f32>,
    @location(2) color: vec4<f32>,
    @location(3) tex_coord: vec2<f32>,
};

@vertex
fn vs_main(v: VertexIn) -> VertexOut {
    var out: VertexOut;
    out.clip = globals.view_projection * vec4<f32>(v.position, 1.0);
    out.position = v.position;
    out.normal = v.normal;
    out.color = v.color;
    // X3D t runs up the image, texture rows run down.
    out.tex_coord = vec2<f32>(v.tex_coord.x, 1.0 - v.tex_coord.y);
    return out;
}

const PI: f32 = 3.14159265358979;

// x · y of 17.2.2.3: never negative.
fn pdot(x: vec3<f32>, y: vec3<f32>) -> f32 {
    return max(0.0, dot(x, y));
}

// on × attenuation × spot of light i at point p, with L (towards the light).
struct Incidence {
    factor: f32,
    to_light: vec3<f32>,
};

fn incidence(light: Light, p: vec3<f32>) -> Incidence {
    var result: Incidence;
    let kind = u32(light.location_kind.w);
    if kind == 0u {
        result.factor = 1.0;
        result.to_light = -light.direction_ambient.xyz;
        return result;
    }
    let offset = light.location_kind.xyz - p;
    let distance = length(offset);
    result.to_light = select(vec3<f32>(0.0, 0.0, 1.0), offset / distance, distance > 0.0);
    if distance > light.attenuation_radius.w {
        result.factor = 0.0;
        return result;
    }
    let c = light.attenuation_radius.xyz;
    var factor = 1.0 / max(c.x + c.y * distance + c.z * distance * distance, 1.0);
    if kind == 2u {
        let spot_angle = acos(clamp(dot(-result.to_light, light.direction_ambient.xyz), -1.0, 1.0));
        let beam = light.spot.x;
        let cut_off = light.spot.y;
        if spot_angle >= cut_off {
            factor = 0.0;
        } else if spot_angle > beam {
            factor = factor * (spot_angle - cut_off) / (beam - cut_off);
        }
    }
    result.factor = factor;
    return result;
}

fn phong(m: Material, diffuse: vec3<f32>, p: vec3<f32>, n: vec3<f32>, v: vec3<f32>) -> vec3<f32> {
    var sum = vec3<f32>(0.0);
    let ambient_parameter = m.params.x * diffuse;
    for (var i = 0u; i < globals.counts.y; i = i + 1u) {
        if (draw.misc.x & (1u << i)) == 0u {
            continue;
        }
        let light = globals.lights[i];
        let inc = incidence(light, p);
        if inc.factor <= 0.0 {
            continue;
        }
        let l = inc.to_light;
        let intensity = light.color_intensity.w;
        let ambient = light.direction_ambient.w * ambient_parameter;
        let diffuse_term = intensity * diffuse * pdot(n, l);
        var specular_term = vec3<f32>(0.0);
        let half_sum = l + v;
        if dot(half_sum, half_sum) > 0.0 && dot(n, l) > 0.0 {
            let h = normalize(half_sum);
            let shininess = m.specular_shininess.w;
            let lobe = select(pow(pdot(n, h), shininess), 1.0, shininess <= 0.0);
            specular_term = intensity * m.specular_shininess.rgb * lobe;
        }
        sum = sum + light.color_intensity.rgb * inc.factor * (ambient + diffuse_term + specular_term);
    }
    return m.emissive_model.rgb + sum;
}

// The glTF 2.0 metallic-roughness BRDF (glTF 2.0 Appendix B), as 17.2.2.6 requires.
fn physical(m: Material, base: vec3<f32>, p: vec3<f32>, n: vec3<f32>, v: vec3<f32>) -> vec3<f32> {
    let metallic = clamp(m.params.y, 0.0, 1.0);
    let roughness = clamp(m.params.z, 0.0, 1.0);
    let alpha = roughness * roughness;
    let alpha2 = alpha * alpha;
    let c_diff = mix(base, vec3<f32>(0.0), metallic);
    let f0 = mix(vec3<f32>(0.04), base, metallic);
    var sum = vec3<f32>(0.0);
    for (var i = 0u; i < globals.counts.y; i = i + 1u) {
        if (draw.misc.x & (1u << i)) == 0u {
            continue;
        }
        let light = globals.lights[i];
        let inc = incidence(light, p);
        let l = inc.to_light;
        let n_dot_l = pdot(n, l);
        if inc.factor <= 0.0 || n_dot_l <= 0.0 {
            continue;
        }
        let half_sum = l + v;
        let h = select(n, normalize(half_sum), dot(half_sum, half_sum) > 0.0);
        let n_dot_v = pdot(n, v);
        let n_dot_h = pdot(n, h);
        let v_dot_h = pdot(v, h);
        let fresnel = f0 + (vec3<f32>(1.0) - f0) * pow(1.0 - v_dot_h, 5.0);
        let ggx_v = n_dot_l * sqrt(n_dot_v * n_dot_v * (1.0 - alpha2) + alpha2);
        let ggx_l = n_dot_v * sqrt(n_dot_l * n_dot_l * (1.0 - alpha2) + alpha2);
        let ggx = ggx_v + ggx_l;
        let visibility = select(0.0, 0.5 / ggx, ggx > 0.0);
        let d_denominator = n_dot_h * n_dot_h * (alpha2 - 1.0) + 1.0;
        let distribution = alpha2 / (PI * d_denominator * d_denominator);
        let f_diffuse = (vec3<f32>(1.0) - fresnel) * c_diff / PI;
        let f_specular = fresnel * visibility * distribution;
        sum = sum + light.color_intensity.rgb * light.color_intensity.w * inc.factor * n_dot_l * (f_diffuse + f_specular);
    }
    return m.emissive_model.rgb + sum;
}

fn apply_fog(color: vec3<f32>, p: vec3<f32>) -> vec3<f32> {
    let kind = globals.counts.x;
    if kind == 0u {
        return color;
    }
    let range = globals.fog_color_range.w;
    let d = length(p);
    var f = 0.0;
    if d < range {
        if kind == 1u {
            f = (range - d) / range;
        } else {
            f = exp(-d / (range - d));
        }
    }
    return mix(globals.fog_color_range.rgb, color, f);
}

@fragment
fn fs_main(in: VertexOut, @builtin(front_facing) front_facing: bool) -> @location(0) vec4<f32> {
    var m = draw.front;
    var n = in.normal;
    if !front_facing {
        m = draw.back;
        n = -n;
    }
    let model = u32(m.emissive_model.w);
    // applyColorPerVertex: the Color node's colour replaces the material colour.
    var color = vec4<f32>(select(m.diffuse_alpha.rgb, m.emissive_model.rgb, model == 0u), m.diffuse_alpha.a);
    if draw.misc.y == 1u {
        color = vec4<f32>(in.color.rgb, color.a);
    } else if draw.misc.y == 2u {
        color = in.color;
    }
    // mixTexture. Sampled unconditionally: derivatives need uniform control flow.
    let sample = textureSample(base_texture, base_sampler, in.tex_coord);
    if m.flags.x != 0u {
        let rgb = select(color.rgb * sample.rgb, sample.rgb, m.flags.y != 0u);
        let a = select(color.a * sample.a, sample.a, m.flags.z != 0u);
        color = vec4<f32>(rgb, a);
    }
    if color.a < draw.cutoff.x {
        discard;
    }
    var rgb = color.rgb;
    let len = length(n);
    if model != 0u {
        if len > 0.0 {
            n = n / len;
        }
        let v = select(vec3<f32>(0.0, 0.0, 1.0), normalize(-in.position), length(in.position) > 0.0);
        if model == 1u {
            rgb = phong(m, color.rgb, in.position, n, v);
        } else {
            rgb = physical(m, color.rgb, in.position, n, v);
        }
    }
    return vec4<f32>(clamp(apply_fog(rgb, in.position), vec3<f32>(0.0), vec3<f32>(1.0)), clamp(color.a, 0.0, 1.0));
}
