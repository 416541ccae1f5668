//! The lighting math at the extremes, as property tests.
//!
//! 1. What the flattener makes of extreme light fields (NaN, ±∞, ±3.4e38, denormals, −0,
//!    out-of-range values) lies within the draw list's guarantees.
//! 2. The lighting equations themselves (`src/render/lighting.wgsl`, the code the renderer
//!    runs) are run on the GPU — lavapipe in CI — over inputs anywhere within those
//!    guarantees, extremes included: every result is finite and non-negative, attenuation
//!    and spot factors stay in [0, 1], and the decisions at the bounds are exact (a point
//!    at exactly the radius is lit; one beyond is not; Table 17.4's spot cases; Table
//!    17.5's fog cases), and the sRGB transfer functions of the physical model keep
//!    colours in [0, 1] and invert each other.
//!
//! Without a graphics adapter the GPU part is skipped, loudly
//! ([`x3dcheck::render::adapter_for_test`]).
#![cfg(feature = "render")]

use std::path::Path;

use proptest::prelude::*;
use x3dcheck::config::CheckConfig;
use x3dcheck::render::draw_list::{Light, LightKind};
use x3dcheck::render::{preview, ImageSize, Quality, RenderArgs, Settings, Shading};

/// The compute kernel: each case through the lighting functions.
const KERNEL: &str = r#"
struct Case {
    light: Light,
    diffuse_shininess: vec4<f32>,
    specular_metallic: vec4<f32>,
    ambient_roughness: vec4<f32>,
    point: vec4<f32>,
    normal: vec4<f32>,
    view: vec4<f32>,
    fog: vec4<f32>, // kind, range, distance
};

@group(0) @binding(0) var<storage, read> cases: array<Case>;
@group(0) @binding(1) var<storage, read_write> results: array<vec4<f32>>;

@compute @workgroup_size(64)
fn main(@builtin(global_invocation_id) id: vec3<u32>) {
    let i = id.x;
    if i >= arrayLength(&cases) {
        return;
    }
    let c = cases[i];
    var s: Surface;
    s.diffuse = c.diffuse_shininess.xyz;
    s.shininess = c.diffuse_shininess.w;
    s.specular = c.specular_metallic.xyz;
    s.metallic = c.specular_metallic.w;
    s.ambient = c.ambient_roughness.xyz;
    s.roughness = c.ambient_roughness.w;
    s.emissive = vec3<f32>(0.0);
    s.occlusion = 1.0;
    let factor = incidence(c.light, c.point.xyz).factor;
    let fog = fog_interpolant(u32(c.fog.x), c.fog.y, c.fog.z);
    results[3u * i] = vec4<f32>(light_phong(c.light, s, c.point.xyz, c.normal.xyz, c.view.xyz), factor);
    results[3u * i + 1u] = vec4<f32>(light_physical(c.light, s, c.point.xyz, c.normal.xyz, c.view.xyz), fog);
    let encoded = linear_to_srgb(c.diffuse_shininess.xyz);
    results[3u * i + 2u] = vec4<f32>(encoded, srgb_to_linear(encoded).x);
}
"#;

/// One input of the kernel, laid out as its `Case`.
#[derive(Clone, Debug)]
struct Case {
    light: Light,
    diffuse: [f32; 3],
    shininess: f32,
    specular: [f32; 3],
    metallic: f32,
    ambient: [f32; 3],
    roughness: f32,
    point: [f32; 3],
    normal: [f32; 3],
    view: [f32; 3],
    fog: [f32; 3],
}

impl Case {
    fn words(&self) -> Vec<f32> {
        let l = &self.light;
        let kind = match l.kind {
            LightKind::Directional => 0.0,
            LightKind::Point => 1.0,
            LightKind::Spot => 2.0,
            LightKind::Environment => 3.0,
        };
        let v4 = |a: [f32; 3], w: f32| [a[0], a[1], a[2], w];
        [
            v4(l.color, l.intensity),
            v4(l.location, kind),
            v4(l.direction, l.ambient_intensity),
            v4(l.attenuation, l.radius),
            [l.beam_width, l.cut_off_angle, 0.0, 0.0],
            v4(self.diffuse, self.shininess),
            v4(self.specular, self.metallic),
            v4(self.ambient, self.roughness),
            v4(self.point, 0.0),
            v4(self.normal, 0.0),
            v4(self.view, 0.0),
            v4(self.fog, 0.0),
        ]
        .concat()
    }
}

/// What the kernel returns for one case.
#[derive(Debug)]
struct Lit {
    phong: [f32; 3],
    factor: f32,
    physical: [f32; 3],
    fog: f32,
    /// The diffuse colour encoded to sRGB, and its red decoded again.
    encoded: [f32; 3],
    round_trip: f32,
}

/// Runs the cases through the kernel.
fn run(cases: &[Case]) -> Vec<Lit> {
    use wgpu::util::DeviceExt;
    pollster::block_on(async {
        let (device, queue) = x3dcheck::render::open_device().await.expect("a device");
        let source = format!("{}{KERNEL}", x3dcheck::render::LIGHTING_WGSL);
        let module = device.create_shader_module(wgpu::ShaderModuleDescriptor {
            label: Some("lighting kernel"),
            source: wgpu::ShaderSource::Wgsl(source.into()),
        });
        let pipeline = device.create_compute_pipeline(&wgpu::ComputePipelineDescriptor {
            label: None,
            layout: None,
            module: &module,
            entry_point: Some("main"),
            compilation_options: Default::default(),
            cache: None,
        });
        let words: Vec<f32> = cases.iter().flat_map(Case::words).collect();
        let input = device.create_buffer_init(&wgpu::util::BufferInitDescriptor {
            label: None,
            contents: bytemuck::cast_slice(&words),
            usage: wgpu::BufferUsages::STORAGE,
        });
        let size = (cases.len() * 3 * 16) as u64;
        let output = device.create_buffer(&wgpu::BufferDescriptor {
            label: None,
            size,
            usage: wgpu::BufferUsages::STORAGE | wgpu::BufferUsages::COPY_SRC,
            mapped_at_creation: false,
        });
        let read = device.create_buffer(&wgpu::BufferDescriptor {
            label: None,
            size,
            usage: wgpu::BufferUsages::COPY_DST | wgpu::BufferUsages::MAP_READ,
            mapped_at_creation: false,
        });
        let group = device.create_bind_group(&wgpu::BindGroupDescriptor {
            label: None,
            layout: &pipeline.get_bind_group_layout(0),
            entries: &[
                wgpu::BindGroupEntry {
                    binding: 0,
                    resource: input.as_entire_binding(),
                },
                wgpu::BindGroupEntry {
                    binding: 1,
                    resource: output.as_entire_binding(),
                },
            ],
        });
        let mut encoder = device.create_command_encoder(&Default::default());
        {
            let mut pass = encoder.begin_compute_pass(&Default::default());
            pass.set_pipeline(&pipeline);
            pass.set_bind_group(0, &group, &[]);
            pass.dispatch_workgroups((cases.len() as u32).div_ceil(64), 1, 1);
        }
        encoder.copy_buffer_to_buffer(&output, 0, &read, 0, size);
        queue.submit([encoder.finish()]);
        let slice = read.slice(..);
        slice.map_async(wgpu::MapMode::Read, |r| r.expect("mapped"));
        device
            .poll(wgpu::PollType::wait_indefinitely())
            .expect("the kernel ran");
        let data = slice.get_mapped_range().expect("mapped range");
        let floats: &[f32] = bytemuck::cast_slice(&data);
        floats
            .chunks_exact(12)
            .map(|c| Lit {
                phong: [c[0], c[1], c[2]],
                factor: c[3],
                physical: [c[4], c[5], c[6]],
                fog: c[7],
                encoded: [c[8], c[9], c[10]],
                round_trip: c[11],
            })
            .collect()
    })
}

/// Floats from the extremes and the ordinary, as a f32 strategy over a range.
fn extreme(lo: f32, hi: f32) -> impl Strategy<Value = f32> {
    let edges: Vec<f32> = [
        0.0,
        -0.0,
        f32::MIN_POSITIVE,
        1e-45,
        1.0,
        f32::MAX,
        -f32::MAX,
        lo,
        hi,
        f32::EPSILON,
        1.0 - f32::EPSILON,
    ]
    .into_iter()
    .filter(|v| (lo..=hi).contains(v))
    .collect();
    prop_oneof![
        proptest::sample::select(edges),
        lo..=hi,
        (lo.max(-1e3)..=hi.min(1e3)),
    ]
}

fn unit_or_zero() -> impl Strategy<Value = [f32; 3]> {
    prop_oneof![
        Just([0.0f32; 3]),
        (-1.0f32..=1.0, -1.0f32..=1.0, -1.0f32..=1.0).prop_map(|(x, y, z)| {
            let l = (x * x + y * y + z * z).sqrt();
            if l > 0.0 {
                [x / l, y / l, z / l]
            } else {
                [0.0, 0.0, 1.0]
            }
        }),
        Just([1.0, 0.0, 0.0]),
        Just([0.0, 0.0, -1.0]),
    ]
}

fn color() -> impl Strategy<Value = [f32; 3]> {
    (extreme(0.0, 1.0), extreme(0.0, 1.0), extreme(0.0, 1.0)).prop_map(|(r, g, b)| [r, g, b])
}

fn position() -> impl Strategy<Value = [f32; 3]> {
    let c = || extreme(-f32::MAX, f32::MAX);
    (c(), c(), c()).prop_map(|(x, y, z)| [x, y, z])
}

/// Lights anywhere within the draw list's guarantees.
fn light() -> impl Strategy<Value = Light> {
    (
        prop_oneof![
            Just(LightKind::Directional),
            Just(LightKind::Point),
            Just(LightKind::Spot)
        ],
        color(),
        extreme(0.0, 1e15),
        extreme(0.0, 1.0),
        position(),
        unit_or_zero(),
        (
            extreme(0.0, f32::MAX),
            extreme(0.0, f32::MAX),
            extreme(0.0, f32::MAX),
        ),
        extreme(0.0, f32::MAX),
        (extreme(0.0, std::f32::consts::FRAC_PI_2), extreme(0.0, 1.0)),
    )
        .prop_map(
            |(kind, color, intensity, ambient, location, direction, c, radius, (cut, beam))| {
                let attenuation = if c == (0.0, 0.0, 0.0) {
                    [1.0, 0.0, 0.0]
                } else {
                    [c.0, c.1, c.2]
                };
                Light {
                    kind,
                    color,
                    intensity,
                    ambient_intensity: ambient,
                    location,
                    direction: if direction == [0.0; 3] {
                        [0.0, 0.0, -1.0]
                    } else {
                        direction
                    },
                    attenuation,
                    radius,
                    beam_width: beam * cut,
                    cut_off_angle: cut,
                }
            },
        )
}

fn case() -> impl Strategy<Value = Case> {
    (
        light(),
        (color(), extreme(0.0, 128.0)),
        (color(), extreme(0.0, 1.0)),
        (color(), extreme(0.0, 1.0)),
        position(),
        unit_or_zero(),
        unit_or_zero(),
        (
            0u8..3,
            extreme(f32::MIN_POSITIVE, f32::MAX),
            extreme(0.0, f32::MAX),
        ),
    )
        .prop_map(
            |(
                light,
                (diffuse, shininess),
                (specular, metallic),
                (ambient, roughness),
                point,
                normal,
                view,
                (kind, range, d),
            )| Case {
                light,
                diffuse,
                shininess,
                specular,
                metallic,
                ambient,
                roughness,
                point,
                normal,
                view,
                fog: [f32::from(kind), range, d],
            },
        )
}

/// A case where N, V and L coincide (a mirror's peak: N · H = 1, where the BRDF's
/// distribution and visibility are largest), or graze (N · V near 0).
fn aligned_case() -> impl Strategy<Value = Case> {
    (case(), unit_or_zero(), prop::bool::ANY).prop_map(|(mut c, u, grazing)| {
        let u = if u == [0.0; 3] { [0.0, 0.0, 1.0] } else { u };
        c.light.kind = LightKind::Directional;
        c.light.direction = u.map(|x| -x);
        c.normal = u;
        c.view = if grazing {
            // Perpendicular to u, nudged by 1e-7 towards it.
            let p = if u[0].abs() < 0.9 {
                [1.0, 0.0, 0.0]
            } else {
                [0.0, 1.0, 0.0]
            };
            let d: f32 = p.iter().zip(&u).map(|(a, b)| a * b).sum();
            let t = [0, 1, 2].map(|k| p[k] - d * u[k] + 1e-7 * u[k]);
            let l = t.iter().map(|x| x * x).sum::<f32>().sqrt();
            t.map(|x| x / l)
        } else {
            u
        };
        c
    })
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 4, ..ProptestConfig::default() })]

    /// Each proptest case is a batch of 2048 kernel cases (one GPU dispatch).
    #[test]
    fn the_lighting_equations_stay_finite_and_in_range(
        cases in proptest::collection::vec(prop_oneof![case(), aligned_case()], 2048)
    ) {
        if !x3dcheck::render::adapter_for_test("the_lighting_equations_stay_finite_and_in_range") {
            return Ok(());
        }
        for (c, lit) in cases.iter().zip(run(&cases)) {
            for v in lit.phong.iter().chain(&lit.physical) {
                prop_assert!(v.is_finite() && *v >= 0.0, "{c:?} gave {lit:?}");
            }
            prop_assert!((0.0..=1.0).contains(&lit.factor), "{c:?} gave {lit:?}");
            prop_assert!((0.0..=1.0).contains(&lit.fog), "{c:?} gave {lit:?}");
            for v in lit.encoded {
                prop_assert!((0.0..=1.0).contains(&v), "{c:?} gave {lit:?}");
            }
            prop_assert!((lit.round_trip - c.diffuse[0]).abs() < 1e-4, "{c:?} gave {lit:?}");
        }
    }
}

/// A white point light at (r, 0, 0) over the origin, facing it.
fn point_light(radius: f32, location_x: f32) -> Case {
    Case {
        light: Light {
            kind: LightKind::Point,
            color: [1.0; 3],
            intensity: 1.0,
            ambient_intensity: 0.0,
            location: [location_x, 0.0, 0.0],
            direction: [0.0, 0.0, -1.0],
            attenuation: [1.0, 0.0, 0.0],
            radius,
            beam_width: 0.5,
            cut_off_angle: 1.0,
        },
        diffuse: [1.0; 3],
        shininess: 0.0,
        specular: [0.0; 3],
        metallic: 0.0,
        ambient: [0.0; 3],
        roughness: 1.0,
        point: [0.0; 3],
        normal: [1.0, 0.0, 0.0],
        view: [1.0, 0.0, 0.0],
        fog: [0.0, 1.0, 0.0],
    }
}

#[test]
fn decisions_at_the_bounds_are_exact() {
    if !x3dcheck::render::adapter_for_test("decisions_at_the_bounds_are_exact") {
        return;
    }
    let next_up = |v: f32| f32::from_bits(v.to_bits() + 1);
    let mut cases = Vec::new();
    // The radius: a point at exactly the radius is lit, one ulp beyond is not.
    for r in [1.0f32, 2.0, 1024.0, 0.5] {
        cases.push(point_light(r, r));
        cases.push(point_light(r, next_up(r)));
    }
    // Spot (Table 17.4): straight down the beam, factor 1; at exactly the cut-off, 0.
    let mut spot = point_light(10.0, 4.0);
    spot.light.kind = LightKind::Spot;
    spot.light.direction = [-1.0, 0.0, 0.0];
    cases.push(spot.clone());
    let mut zero_cut = spot.clone();
    zero_cut.light.cut_off_angle = 0.0;
    zero_cut.light.beam_width = 0.0;
    cases.push(zero_cut);
    // Fog (Table 17.5): at the visibility range, 0; at the eye, 1; no fog, 1.
    let mut fog = point_light(1.0, 1.0);
    fog.fog = [1.0, 8.0, 8.0];
    cases.push(fog.clone());
    fog.fog = [2.0, 8.0, 8.0];
    cases.push(fog.clone());
    fog.fog = [1.0, 8.0, 0.0];
    cases.push(fog.clone());
    fog.fog = [0.0, 8.0, 1e30];
    cases.push(fog);
    // Attenuation 1 / max(c1 + c2 d + c3 d², 1): below 1 it is 1.
    let mut attenuated = point_light(100.0, 2.0);
    attenuated.light.attenuation = [0.25, 0.0, 0.0];
    cases.push(attenuated.clone());
    attenuated.light.attenuation = [0.0, 0.0, 1.0];
    cases.push(attenuated);

    let lit = run(&cases);
    for pair in lit[..8].chunks(2) {
        assert_eq!(pair[0].factor, 1.0, "{pair:?}");
        assert_eq!(pair[1].factor, 0.0, "{pair:?}");
        assert_eq!(pair[1].phong, [0.0; 3], "{pair:?}");
    }
    assert_eq!(lit[8].factor, 1.0, "down the beam: {:?}", lit[8]);
    assert_eq!(lit[9].factor, 0.0, "cut-off 0: {:?}", lit[9]);
    assert_eq!(lit[10].fog, 0.0, "linear fog at its range");
    assert_eq!(lit[11].fog, 0.0, "exponential fog at its range");
    assert_eq!(lit[12].fog, 1.0, "linear fog at the eye");
    assert_eq!(lit[13].fog, 1.0, "no fog");
    assert_eq!(lit[14].factor, 1.0, "c1 = 0.25 is below 1");
    assert_eq!(lit[15].factor, 0.25, "1 / (2²)");
    // A white light straight on a white Phong surface: diffuse exactly 1 (N · L = 1).
    assert_eq!(lit[0].phong, [1.0; 3]);

    // sRGB (IEC 61966-2-1): 0 and 1 stay; linear 0.5 is 0.7354, 0.2140 is 0.5, and
    // the linear segment below 0.0031308 is 12.92 x.
    let mut colours = Vec::new();
    for (linear, encoded) in [
        (0.0, 0.0),
        (1.0, 1.0),
        (0.5, 0.735_357),
        (0.214_041, 0.5),
        (0.002, 0.025_84),
    ] {
        let mut case = point_light(1.0, 1.0);
        case.diffuse = [linear; 3];
        colours.push((case, encoded));
    }
    let cases: Vec<Case> = colours.iter().map(|(c, _)| c.clone()).collect();
    for ((case, expected), lit) in colours.iter().zip(run(&cases)) {
        assert!(
            (lit.encoded[0] - expected).abs() < 1e-4,
            "{case:?}: {lit:?}"
        );
        assert!(
            (lit.round_trip - case.diffuse[0]).abs() < 1e-5,
            "{case:?}: {lit:?}"
        );
    }
}

/// What the flattener makes of a light node with these fields.
fn flattened_lights(fields: &str) -> Vec<Light> {
    let source = format!(
        "<X3D profile='Full' version='4.0'><Scene><NavigationInfo headlight='false'/>\
         <Transform scale='3e38 -0 1e-40'><SpotLight {fields}/><PointLight {fields}/>\
         <DirectionalLight {fields}/></Transform><Shape><Box/></Shape></Scene></X3D>"
    );
    let x3dcheck::check::Checked {
        mut report,
        document: doc,
        ..
    } = x3dcheck::check::check_document("lights.x3d", source.as_bytes(), &CheckConfig::default());
    let args = RenderArgs {
        render: None,
        size: ImageSize {
            width: 8,
            height: 8,
        },
        quality: Quality::Fast,
        camera: "auto".to_string(),
        island: 1,
    };
    let settings = Settings {
        shading: Shading::Gouraud,
        msaa_samples: 1,
        supersampling: 1,
    };
    let preview = preview(
        &args,
        settings,
        Path::new("lights.x3d"),
        None,
        source.as_bytes(),
        doc.as_ref(),
        &mut report,
    )
    .expect("a preview");
    preview.list().layers[0].lights.clone()
}

fn field_text() -> impl Strategy<Value = String> {
    prop_oneof![
        Just("NaN".to_string()),
        Just("INF".to_string()),
        Just("-INF".to_string()),
        Just("3.4028235e38".to_string()),
        Just("-3.4028235e38".to_string()),
        Just("1e39".to_string()),
        Just("1e-45".to_string()),
        Just("-0".to_string()),
        (-1e6f32..1e6).prop_map(|v| v.to_string()),
        (-2.0f32..2.0).prop_map(|v| v.to_string()),
    ]
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 64, ..ProptestConfig::default() })]

    #[test]
    fn extreme_light_fields_flatten_within_the_guarantees(
        values in proptest::collection::vec(field_text(), 17)
    ) {
        let v = |i: usize| values[i].as_str();
        let fields = format!(
            "color='{} {} {}' intensity='{}' ambientIntensity='{}' location='{} {} {}' \
             direction='{} {} {}' attenuation='{} {} {}' radius='{}' beamWidth='{}' cutOffAngle='{}'",
            v(0), v(1), v(2), v(3), v(4), v(5), v(6), v(7), v(8), v(9), v(10), v(11), v(12),
            v(13), v(14), v(15), v(16)
        );
        for light in flattened_lights(&fields) {
            let finite = |a: &[f32]| a.iter().all(|c| c.is_finite());
            prop_assert!(light.color.iter().all(|c| (0.0..=1.0).contains(c)), "{light:?}");
            prop_assert!((0.0..=1e15).contains(&light.intensity), "{light:?}");
            prop_assert!((0.0..=1.0).contains(&light.ambient_intensity), "{light:?}");
            prop_assert!(finite(&light.location) && finite(&light.direction), "{light:?}");
            let length: f32 = light.direction.iter().map(|c| c * c).sum::<f32>().sqrt();
            prop_assert!((length - 1.0).abs() < 1e-5, "{light:?}");
            prop_assert!(finite(&light.attenuation), "{light:?}");
            prop_assert!(light.attenuation.iter().all(|c| *c >= 0.0), "{light:?}");
            prop_assert!(light.attenuation != [0.0; 3], "{light:?}");
            prop_assert!(light.radius >= 0.0 && !light.radius.is_nan(), "{light:?}");
            prop_assert!(
                (0.0..=light.cut_off_angle).contains(&light.beam_width)
                    && light.cut_off_angle <= std::f32::consts::FRAC_PI_2,
                "{light:?}"
            );
        }
    }
}
