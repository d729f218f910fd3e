//! Any camera, any scene, no display: no panic, no NaN, a clear message.
#[allow(dead_code)]
#[path = "../src/main.rs"]
mod raytracer;

use raytracer::*;
use std::f64::consts::{FRAC_PI_2, TAU};
use std::process::Command;

/// A small deterministic pseudo-random generator (xorshift64*), so a failure can be replayed.
struct Random {
    state: u64,
}

impl Random {
    fn new(seed: u64) -> Random {
        Random { state: seed }
    }
    /// A number from 0 up to 1.
    fn next(&mut self) -> f64 {
        self.state ^= self.state >> 12;
        self.state ^= self.state << 25;
        self.state ^= self.state >> 27;
        let bits = self.state.wrapping_mul(0x2545_f491_4f6c_dd1d) >> 11; // the top 53 bits
        bits as f64 / (1u64 << 53) as f64
    }
    fn between(&mut self, low: f64, high: f64) -> f64 {
        low + (high - low) * self.next()
    }
    fn point(&mut self, size: f64) -> Vec3 {
        vec3(
            self.between(-size, size),
            self.between(-size, size),
            self.between(-size, size),
        )
    }
}

fn material(random: &mut Random) -> Material {
    let color = vec3(random.next(), random.next(), random.next());
    let reflectivity = if random.next() < 0.3 {
        1.0
    } else {
        random.next()
    };
    Material {
        color,
        reflectivity,
        checkered: random.next() < 0.5,
    }
}

fn random_scene(random: &mut Random) -> Scene {
    let count = (random.next() * 5.0) as usize;
    let objects = (0..count)
        .map(|_| {
            let shape = if random.next() < 0.7 {
                let radius = [0.0, 0.01, 1.0, 3.0, 1e4][(random.next() * 5.0) as usize];
                Shape::Sphere {
                    center: random.point(5.0),
                    radius,
                }
            } else {
                let normal = random.point(1.0).normalize();
                Shape::Plane {
                    normal,
                    offset: random.between(-3.0, 3.0),
                }
            };
            (shape, material(random))
        })
        .collect();
    Scene {
        objects,
        light: random.point(6.0),
        sky: vec3(0.5, 0.7, 1.0),
    }
}

fn random_camera(random: &mut Random) -> Camera {
    let far = if random.next() < 0.1 { 1e4 } else { 6.0 };
    let pitch = match (random.next() * 4.0) as usize {
        0 => FRAC_PI_2,
        1 => -FRAC_PI_2,
        _ => random.between(-FRAC_PI_2, FRAC_PI_2),
    };
    Camera {
        position: random.point(far),
        yaw: random.between(-3.0 * TAU, 3.0 * TAU),
        pitch,
    }
}

/// The primary ray through the centre of pixel (x, y) of the 3D view.
fn primary_ray(camera: &Camera, x: usize, y: usize) -> Ray {
    camera.primary_rays()(x as f64 + 0.5, y as f64 + 0.5)
}

fn valid(color: Vec3) -> bool {
    [color.x, color.y, color.z]
        .iter()
        .all(|c| (0.0..=1.0 + 1e-9).contains(c))
}

/// Renders the frame twice and compares: into a fresh buffer, and over one that holds the demo.
fn assert_valid_frame(scene: &Scene, camera: &Camera, case: &str) {
    let mut fresh = vec![0; WIDTH * VIEW];
    render(scene, camera, &mut fresh);
    // The same frame again, over one that holds another picture: every pixel is drawn anew.
    let mut reused = vec![0; WIDTH * VIEW];
    render(&Scene::default(), &Camera::default(), &mut reused);
    render(scene, camera, &mut reused);
    assert!(
        fresh == reused,
        "{case}: the frame depends on what the buffer held"
    );
}

/// Columns and rows apart of the rays `assert_valid_rays` traces: 8 x 9 = 72 rays a pose, their
/// strides prime so that they do not line up with the checkerboard's or the map's spacing.
const COLUMN_STRIDE: usize = 73;
const ROW_STRIDE: usize = 61;

/// Traces a spread of rays through the screen and checks every colour is a valid one.
fn assert_valid_rays(scene: &Scene, camera: &Camera, case: &str) {
    for (x, y) in (0..VIEW)
        .step_by(COLUMN_STRIDE)
        .flat_map(|x| (0..VIEW).step_by(ROW_STRIDE).map(move |y| (x, y)))
    {
        let color = scene.trace(primary_ray(camera, x, y), 0);
        assert!(valid(color), "{case}: pixel {x}, {y} is {color:?}");
    }
}

/// Multiplying by 2^64 / φ (golden ratio) spreads neighbouring seeds over all 64 bits.
const SEED_SPREAD: u64 = 0x9e37_79b9_7f4a_7c15;

/// A seeded random camera pose, in a random scene for every `nth` seed and the demo otherwise.
fn random_case(seed: u64, nth: u64) -> (Scene, Camera) {
    let mut random = Random::new(seed.wrapping_mul(SEED_SPREAD));
    let scene = if seed.is_multiple_of(nth) {
        random_scene(&mut random)
    } else {
        Scene::default()
    };
    (scene, random_camera(&mut random))
}

#[test]
fn a_thousand_camera_poses_and_hundreds_of_random_scenes() {
    for seed in 1..=1200u64 {
        let (scene, camera) = random_case(seed, 3);
        let case = format!("seed {seed}: {camera:?} in {scene:?}");
        assert_valid_rays(&scene, &camera, &case);
        if seed % 60 == 0 {
            assert_valid_frame(&scene, &camera, &case);
        }
    }
}

#[test]
fn hits_are_in_front_of_the_ray_and_on_the_surface() {
    let mut random = Random::new(7);
    let mut sphere_hits = 0;
    let mut plane_hits = 0;
    for case in 0..20_000 {
        let ray = Ray::new(random.point(10.0), random.point(1.0), f64::INFINITY);
        let center = random.point(5.0);
        let radius = random.between(0.0, 4.0);
        let sphere = Shape::Sphere { center, radius };
        let normal = random.point(1.0).normalize();
        let offset = random.between(-5.0, 5.0);
        let plane = Shape::Plane { normal, offset };
        // The test's own roots: |O + tD - C|² = r² gives t = -b ± √(b² - c), b = (O - C).D,
        // c = |O - C|² - r², a hit ahead when the larger root is; (O + tD).N + d = 0 gives one t.
        let oc = ray.origin - center;
        let b = oc.dot(ray.direction);
        let discriminant = b * b - (oc.dot(oc) - radius * radius);
        let far_root = -b + discriminant.max(0.0).sqrt();
        let plane_root = -(ray.origin.dot(normal) + offset) / ray.direction.dot(normal);
        // Where a root is within rounding of 0, or the ray only grazes the sphere, either answer is
        // right: such cases (none with this seed) are left out of the comparison.
        let near_zero = |value: f64| value.abs() < 1e-9;
        if !near_zero(discriminant) && !near_zero(far_root) {
            let hit = sphere.intersect(&ray);
            assert_eq!(
                hit.is_some(),
                discriminant > 0.0 && far_root > 0.0,
                "case {case}"
            );
            if let Some(t) = hit {
                let off_surface = ((at(&ray, t) - center).length() - radius).abs();
                assert!(
                    t > 0.0 && off_surface < 1e-6,
                    "case {case}: sphere hit at t = {t}"
                );
                sphere_hits += 1;
            }
        }
        if !near_zero(plane_root) {
            let hit = plane.intersect(&ray);
            assert_eq!(hit.is_some(), plane_root > 0.0, "case {case}");
            if let Some(t) = hit {
                let off_surface = (at(&ray, t).dot(normal) + offset).abs();
                assert!(
                    t > 0.0 && off_surface < 1e-6,
                    "case {case}: plane hit at t = {t}"
                );
                plane_hits += 1;
            }
        }
    }
    assert!(
        sphere_hits > 100 && plane_hits > 100,
        "{sphere_hits} {plane_hits}"
    );
}

/// The point p(t) = O + tD.
fn at(ray: &Ray, t: f64) -> Vec3 {
    ray.origin + ray.direction * t
}

fn white(reflectivity: f64) -> Material {
    Material {
        color: vec3(1.0, 1.0, 1.0),
        reflectivity,
        checkered: false,
    }
}

fn ball(center: Vec3, radius: f64, material: Material) -> (Shape, Material) {
    (Shape::Sphere { center, radius }, material)
}

fn floor() -> (Shape, Material) {
    (
        Shape::Plane {
            normal: vec3(0.0, 1.0, 0.0),
            offset: 1.0,
        },
        white(0.0),
    )
}

#[test]
fn odd_scenes_render_valid_frames() {
    let sky = vec3(0.5, 0.7, 1.0);
    let light = vec3(0.0, 5.0, 0.0);
    let cases = [
        ("no objects", vec![]),
        ("only a floor", vec![floor()]),
        (
            "radius 0",
            vec![floor(), ball(vec3(0.0, 0.0, -3.0), 0.0, white(0.0))],
        ),
        (
            "huge radius",
            vec![ball(vec3(0.0, 0.0, -1e6 - 5.0), 1e6, white(0.0))],
        ),
        (
            "coincident",
            vec![ball(vec3(0.0, 0.0, -3.0), 1.0, white(0.0)); 2],
        ),
    ];
    for (case, objects) in cases {
        let scene = Scene {
            objects,
            light,
            sky,
        };
        assert_valid_frame(&scene, &Camera::default(), case);
        assert_valid_rays(&scene, &Camera::default(), case);
    }
    // Rays aimed straight at the centres of radius-0 spheres pass them: p² rounds to about 0,
    // either side of it, and such a sphere has no surface to hit (its normal would be (p - C) / 0).
    let mut random = Random::new(5);
    for _ in 0..1000 {
        let center = random.point(5.0);
        let point = Scene {
            objects: vec![ball(center, 0.0, white(0.0))],
            light,
            sky,
        };
        let color = point.trace(Ray::new(vec3(0.0, 0.0, 0.0), center, f64::INFINITY), 0);
        assert_eq!(
            [color.x, color.y, color.z],
            [sky.x, sky.y, sky.z],
            "{center:?}"
        );
    }
    // A ray that grazes the floor and meets it some 10^19 units out, where floor(x) + floor(z)
    // no longer fits an i64: a valid colour, and no overflow panic (the tests' build checks).
    let (plane, _) = floor();
    let checkered = Material {
        checkered: true,
        ..white(0.0)
    };
    let checkered_floor = Scene {
        objects: vec![(plane, checkered)],
        light,
        sky,
    };
    let ray = Ray::new(vec3(0.0, 0.0, 0.0), vec3(1.0, -1e-19, 1.0), f64::INFINITY);
    let color = checkered_floor.trace(ray, 0);
    assert!(valid(color) && color != sky, "{color:?}");
    let empty = Scene {
        objects: vec![],
        light,
        sky,
    };
    let mut frame = vec![0; WIDTH * VIEW];
    render(&empty, &Camera::default(), &mut frame);
    let byte = |channel: f64| (channel * 255.0) as u32; // 0RGB, each channel 0 to 255
    let sky_pixel = byte(sky.x) << 16 | byte(sky.y) << 8 | byte(sky.z);
    assert!((0..VIEW).all(|y| {
        frame[y * WIDTH..y * WIDTH + VIEW]
            .iter()
            .all(|&p| p == sky_pixel)
    }));
}

#[test]
fn a_light_inside_a_sphere_leaves_everything_else_in_shadow() {
    let lamp = ball(vec3(0.0, 2.0, -3.0), 0.5, white(0.0));
    let scene = Scene {
        objects: vec![floor(), lamp],
        light: vec3(0.0, 2.0, -3.0),
        sky: vec3(0.0, 0.0, 0.0),
    };
    let camera = Camera::default();
    for y in (0..VIEW).step_by(8) {
        for x in (0..VIEW).step_by(8) {
            let color = scene.trace(primary_ray(&camera, x, y), 0);
            assert!(
                color.x <= AMBIENT + 1e-9,
                "pixel {x}, {y} is lit: {color:?}"
            );
        }
    }
}

#[test]
fn facing_mirrors_stop_at_the_maximum_depth() {
    // A red mirror floor at y = -1 and a blue mirror ceiling at y = 1, both perfect mirrors, lit
    // from between them. A ray that bounces between them forever brings back the colour of the
    // surface where the recursion stops: bounce 0 is the floor, so an odd MAX_DEPTH ends on the
    // ceiling and an even one on the floor.
    let mirror = |color| Material {
        color,
        reflectivity: 1.0,
        checkered: false,
    };
    let mirror_floor = Shape::Plane {
        normal: vec3(0.0, 1.0, 0.0),
        offset: 1.0,
    };
    let ceiling = Shape::Plane {
        normal: vec3(0.0, -1.0, 0.0),
        offset: 1.0,
    };
    let scene = Scene {
        objects: vec![
            (mirror_floor, mirror(vec3(1.0, 0.0, 0.0))),
            (ceiling, mirror(vec3(0.0, 0.0, 1.0))),
        ],
        light: vec3(0.0, 0.0, -3.0),
        sky: vec3(0.5, 0.7, 1.0),
    };
    let ray = Ray::new(vec3(0.0, 0.0, 0.0), vec3(0.0, -1.0, -0.1), f64::INFINITY);
    let color = scene.trace(ray, 0);
    assert!(valid(color), "{color:?}");
    let ends_on_ceiling = MAX_DEPTH % 2 == 1;
    assert_eq!(color.x == 0.0, ends_on_ceiling, "{color:?}");
    assert_eq!(color.z == 0.0, !ends_on_ceiling, "{color:?}");
    assert!(color.x + color.z > AMBIENT, "lit: {color:?}");
}

/// Runs the program with no display and returns (status, stdout, stderr).
fn run(args: &[&str]) -> (Option<i32>, String, String) {
    let output = Command::new(env!("CARGO_BIN_EXE_raytracer"))
        .args(args)
        .env_remove("DISPLAY")
        .env_remove("WAYLAND_DISPLAY")
        .output()
        .expect("the program runs");
    let text = |bytes: Vec<u8>| String::from_utf8(bytes).unwrap();
    (
        output.status.code(),
        text(output.stdout),
        text(output.stderr),
    )
}

#[test]
fn with_no_display_it_says_so_in_one_line_and_ignores_arguments() {
    for args in [&[][..], &["--help"], &["scene.txt", "2"]] {
        let (status, stdout, stderr) = run(args);
        assert_eq!(status, Some(1), "{args:?}: {stderr}");
        assert_eq!(stderr.lines().count(), 1, "{args:?}: {stderr}");
        // The line says what failed: opening the window, as the X display could not be opened.
        assert!(stderr.contains("cannot open the window"), "{stderr}");
        assert!(stderr.contains("Display") && stdout.is_empty(), "{stderr}");
    }
}

#[test]
fn cameras_on_surfaces_and_far_away_render_valid_frames() {
    let scene = Scene::default();
    let poses = [
        ("on the floor", vec3(0.0, -1.0, -1.0), 0.0, -0.5),
        ("on top of the mirror ball", vec3(0.3, 1.0, -4.5), 1.0, -1.2),
        ("below the floor", vec3(0.0, -5.0, 0.0), 0.0, 0.3),
        ("10,000 units away", vec3(0.0, 0.0, 1e4), 0.0, 0.0),
        (
            "straight up, yaw past 2 pi",
            vec3(0.0, 0.0, 0.0),
            7.0,
            FRAC_PI_2,
        ),
    ];
    for (case, position, yaw, pitch) in poses {
        let camera = Camera {
            position,
            yaw,
            pitch,
        };
        assert_valid_frame(&scene, &camera, case);
        assert_valid_rays(&scene, &camera, case);
    }
}

/// A unit vector at right angles to the unit vector `n`.
fn perpendicular(n: Vec3, random: &mut Random) -> Vec3 {
    let any = random.point(1.0);
    (any - n * any.dot(n)).normalize()
}

#[test]
fn far_away_a_ray_leaving_a_plane_does_not_hit_it_again() {
    // A plane p.N + d = 0 tilted at random, the origin d from it on N's side, and a ray from the
    // origin that grazes it 10^4 to 10^11 units away. The mirror ray leaves the plane, which is
    // alone in the scene, so it brings back the sky; the shadow ray to a light high above that
    // point reaches it.
    let mut random = Random::new(11);
    let sky = vec3(1.0, 1.0, 1.0);
    let mut failures = Vec::new();
    for case in 0..20_000 {
        let normal = random.point(1.0).normalize();
        let offset = random.between(1.0, 5.0);
        let far = 10f64.powf(random.between(4.0, 11.0));
        let on_plane = normal * -offset + perpendicular(normal, &mut random) * far;
        let plane = Shape::Plane { normal, offset };
        // A black half-mirror: what it shows is half the colour its mirror ray brings back.
        let black_mirror = Material {
            color: vec3(0.0, 0.0, 0.0),
            reflectivity: 0.5,
            checkered: false,
        };
        let mirror_scene = Scene {
            objects: vec![(plane, black_mirror)],
            light: vec3(0.0, 0.0, 0.0),
            sky,
        };
        let ray = || Ray::new(vec3(0.0, 0.0, 0.0), on_plane, f64::INFINITY);
        let mirrored = mirror_scene.trace(ray(), 0);
        // A white matte surface straight below the light: fully lit, N.L = 1.
        let lit_scene = Scene {
            objects: vec![(plane, white(0.0))],
            light: on_plane + normal * far,
            sky,
        };
        let lit = lit_scene.trace(ray(), 0);
        if mirrored.x != 0.5 || (lit.x - 1.0).abs() > 1e-3 {
            failures.push((case, far, mirrored.x, lit.x));
        }
    }
    assert!(
        failures.is_empty(),
        "{} of 20000: {:?}",
        failures.len(),
        &failures[..failures.len().min(5)]
    );
}
