// The lighting equations of 19775-1 clause 17 (17.2.2) for one light at one point: the
// part of the shader that property tests run on extreme inputs (tests/lighting.rs).
// Positions are relative to the eye, in world orientation: V = normalize(-p).
//
// Every result is finite for inputs within the draw list's guarantees (intensity at most
// 1e15, colours in [0, 1], finite positions): a light's contribution is capped at
// MAX_RADIANCE (far beyond white), so that a sum of lights or a product with a zero
// occlusion never meets an infinity.

struct Light {
    color_intensity: vec4<f32>,    // rgb colour, intensity
    location_kind: vec4<f32>,      // xyz location, kind (0 directional, 1 point, 2 spot, 3 environment)
    direction_ambient: vec4<f32>,  // xyz unit direction of travel, ambientIntensity
    attenuation_radius: vec4<f32>, // c1, c2, c3, radius
    spot: vec4<f32>,               // beamWidth, cutOffAngle
};

// The inputs of the lighting equations at one point (17.2.2.5, 17.2.2.6).
struct Surface {
    diffuse: vec3<f32>,    // diffuseParameter / baseParameter
    emissive: vec3<f32>,   // emissiveParameter
    specular: vec3<f32>,   // specularParameter
    shininess: f32,        // shininessParameter (× 128 already)
    ambient: vec3<f32>,    // ambientParameter
    metallic: f32,
    roughness: f32,
    occlusion: f32,        // occlusion() as a factor on the sum over the lights
};

const PI: f32 = 3.14159265358979;
const MAX_RADIANCE: f32 = 1e30;
const MAX_SPECULAR: f32 = 1e12;

// x · y of 17.2.2.3: never negative.
fn pdot(x: vec3<f32>, y: vec3<f32>) -> f32 {
    return max(0.0, dot(x, y));
}

fn unit_or_zero(v: vec3<f32>) -> vec3<f32> {
    let len = length(v);
    return select(vec3<f32>(0.0), v / len, len > 0.0);
}

// on × attenuation × spot of a light at point p, with L (towards the light).
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
    if kind == 3u {
        // An EnvironmentLight has no direction: of the equations here only the Phong
        // ambient term reaches (its image-based light is `environment_physical`).
        result.factor = 1.0;
        result.to_light = vec3<f32>(0.0);
        return result;
    }
    let offset = light.location_kind.xyz - p;
    let distance = length(offset);
    result.to_light = select(vec3<f32>(0.0, 0.0, 1.0), offset / distance, distance > 0.0);
    if !(distance <= light.attenuation_radius.w) {
        result.factor = 0.0;
        return result;
    }
    let c = light.attenuation_radius.xyz;
    var factor = 1.0 / max(c.x + c.y * distance + c.z * distance * distance, 1.0);
    if kind == 2u {
        // Table 17.4, in its order.
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

// One light's contribution in the Phong model: on × attenuation × spot × colour ×
// (ambient + diffuse + specular) (17.2.2.5).
fn light_phong(light: Light, s: Surface, p: vec3<f32>, n: vec3<f32>, v: vec3<f32>) -> vec3<f32> {
    let inc = incidence(light, p);
    if inc.factor <= 0.0 {
        return vec3<f32>(0.0);
    }
    let l = inc.to_light;
    let intensity = light.color_intensity.w;
    let ambient = light.direction_ambient.w * s.ambient;
    let diffuse_term = intensity * s.diffuse * pdot(n, l);
    var specular_term = vec3<f32>(0.0);
    let half_sum = l + v;
    if dot(half_sum, half_sum) > 0.0 && dot(n, l) > 0.0 {
        let h = normalize(half_sum);
        let lobe = select(pow(pdot(n, h), s.shininess), 1.0, s.shininess <= 0.0);
        specular_term = intensity * s.specular * lobe;
    }
    let sum = light.color_intensity.rgb * inc.factor * (ambient + diffuse_term + specular_term);
    return min(sum, vec3<f32>(MAX_RADIANCE));
}

// One light's contribution in the physical model: the glTF 2.0 metallic-roughness BRDF
// (glTF 2.0 Appendix B), as 17.2.2.6 requires.
fn light_physical(light: Light, s: Surface, p: vec3<f32>, n: vec3<f32>, v: vec3<f32>) -> vec3<f32> {
    let inc = incidence(light, p);
    let l = inc.to_light;
    let n_dot_l = pdot(n, l);
    if inc.factor <= 0.0 || n_dot_l <= 0.0 {
        return vec3<f32>(0.0);
    }
    let metallic = clamp(s.metallic, 0.0, 1.0);
    let roughness = clamp(s.roughness, 0.0, 1.0);
    let alpha = roughness * roughness;
    let alpha2 = alpha * alpha;
    let c_diff = mix(s.diffuse, vec3<f32>(0.0), metallic);
    let f0 = mix(vec3<f32>(0.04), s.diffuse, metallic);
    let half_sum = l + v;
    let h = select(n, normalize(half_sum), dot(half_sum, half_sum) > 0.0);
    let n_dot_v = pdot(n, v);
    let n_dot_h = pdot(n, h);
    let v_dot_h = pdot(v, h);
    let fresnel = f0 + (vec3<f32>(1.0) - f0) * pow(1.0 - v_dot_h, 5.0);
    let ggx_v = n_dot_l * sqrt(n_dot_v * n_dot_v * (1.0 - alpha2) + alpha2);
    let ggx_l = n_dot_v * sqrt(n_dot_l * n_dot_l * (1.0 - alpha2) + alpha2);
    let ggx = ggx_v + ggx_l;
    let visibility = select(0.0, min(0.5 / ggx, MAX_RADIANCE), ggx > 0.0);
    let d_denominator = n_dot_h * n_dot_h * (alpha2 - 1.0) + 1.0;
    let distribution = min(alpha2 / max(PI * d_denominator * d_denominator, 1e-30), MAX_RADIANCE);
    let f_diffuse = (vec3<f32>(1.0) - fresnel) * c_diff / PI;
    // A mirror's peak, capped where any light already saturates (intensity ≤ 1e15).
    let f_specular = min(fresnel * visibility * distribution, vec3<f32>(MAX_SPECULAR));
    let radiance = light.color_intensity.rgb * light.color_intensity.w * inc.factor * n_dot_l;
    return min(radiance * (f_diffuse + f_specular), vec3<f32>(MAX_RADIANCE));
}

// The fog interpolant f0 of Table 17.5: 1 without fog (kind 0), (range − d) / range for
// LINEAR (1), exp(−d / (range − d)) for EXPONENTIAL (2), 0 beyond the range.
fn fog_interpolant(kind: u32, range: f32, d: f32) -> f32 {
    if kind == 0u {
        return 1.0;
    }
    if !(d < range) {
        return 0.0;
    }
    if kind == 1u {
        return (range - d) / range;
    }
    return exp(-d / (range - d));
}

// The sRGB transfer functions (IEC 61966-2-1, the encoding glTF 2.0 gives colour
// textures): stored values to linear light and back, per channel, for values in [0, 1].
fn srgb_to_linear(c: vec3<f32>) -> vec3<f32> {
    let low = c / 12.92;
    let high = pow((max(c, vec3<f32>(0.0)) + vec3<f32>(0.055)) / 1.055, vec3<f32>(2.4));
    return select(high, low, c <= vec3<f32>(0.04045));
}

fn linear_to_srgb(c: vec3<f32>) -> vec3<f32> {
    let low = c * 12.92;
    let high = 1.055 * pow(max(c, vec3<f32>(0.0)), vec3<f32>(1.0 / 2.4)) - vec3<f32>(0.055);
    return select(high, low, c <= vec3<f32>(0.0031308));
}
