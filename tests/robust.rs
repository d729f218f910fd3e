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
    /// A number from 0 up to 1, never 1 itself.
    fn next(&mut self) -> f64 {
        // xorshift64*'s published shifts and multiplier (Vigna, 2016).
        self.state ^= self.state >> 12;
        self.state ^= self.state << 25;
        self.state ^= self.state >> 27;
        let bits = self.state.wrapping_mul(0x2545_f491_4f6c_dd1d) >> 11; // the top 53 bits
        bits as f64 / (1u64 << 53) as f64
    }
    /// A whole number from 0 to n - 1, each as likely.
    fn below(&mut self, n: usize) -> usize {
        // next() < 1, so next() * n < n: its floor is one of 0 to n - 1.
        (self.next() * n as f64).floor() as usize
    }
    /// A number from `low` up to `high`.
    fn between(&mut self, low: f64, high: f64) -> f64 {
        low + (high - low) * self.next()
    }
    /// A point in the cube from -size to size on each axis.
    fn point(&mut self, size: f64) -> Vec3 {
        vec3(
            self.between(-size, size),
            self.between(-size, size),
            self.between(-size, size),
        )
    }
}

/// The share of random materials that are perfect mirrors (reflectivity 1), which can bounce a ray
/// on to the maximum depth; the rest get a reflectivity anywhere from 0 to 1.
const PERFECT_MIRROR_SHARE: f64 = 0.3;
/// The share of random materials that are checkered.
const CHECKERED_SHARE: f64 = 0.5;

/// A random colour and finish.
fn random_material(random: &mut Random) -> Material {
    let color = vec3(random.next(), random.next(), random.next());
    let reflectivity = if random.next() < PERFECT_MIRROR_SHARE {
        1.0
    } else {
        random.next()
    };
    Material {
        color,
        reflectivity,
        checkered: random.next() < CHECKERED_SHARE,
    }
}

/// A random scene holds from 0 to this many objects.
const MOST_OBJECTS: usize = 4;
/// The share of spheres among a random scene's objects; the rest are planes.
const SPHERE_SHARE: f64 = 0.7;
/// The radii a random sphere gets: a point, a speck, a ball the demo's size, a big ball, and one so
/// big that every camera near the origin is inside it.
const RADII: [f64; 5] = [0.0, 0.01, 1.0, 3.0, 1e4];
/// Random spheres' centres are within this of the origin on each axis, and the light within
/// `LIGHT_SPREAD`: among the cameras (`NEAR`), so cameras and the light fall inside spheres and on
/// either side of planes.
const OBJECT_SPREAD: f64 = 5.0;
const LIGHT_SPREAD: f64 = 6.0;
/// Random planes pass at most this far from the origin.
const PLANE_SPREAD: f64 = 3.0;

fn random_scene(random: &mut Random) -> Scene {
    let count = random.below(MOST_OBJECTS + 1);
    let objects = (0..count)
        .map(|_| {
            let shape = if random.next() < SPHERE_SHARE {
                Shape::Sphere {
                    center: random.point(OBJECT_SPREAD),
                    radius: RADII[random.below(RADII.len())],
                }
            } else {
                let normal = random.point(1.0).normalize(); // a direction at random
                Shape::Plane {
                    normal,
                    offset: random.between(-PLANE_SPREAD, PLANE_SPREAD),
                }
            };
            (shape, random_material(random))
        })
        .collect();
    Scene {
        objects,
        light: random.point(LIGHT_SPREAD),
        sky: vec3(0.5, 0.7, 1.0), // light blue
    }
}

/// Most cameras are within `NEAR` of the origin on each axis, among the objects; a `FAR_SHARE`
/// of them are within `FAR`, most of them thousands of units away, where rounding errors grow.
const NEAR: f64 = 6.0;
const FAR: f64 = 1e4;
const FAR_SHARE: f64 = 0.1;
/// Yaws go up to this many whole turns either way, to check that angles past 2 pi work.
const MOST_TURNS: f64 = 3.0;

fn random_camera(random: &mut Random) -> Camera {
    let spread = if random.next() < FAR_SHARE { FAR } else { NEAR };
    // A look-at camera's right, V × up, is 0 looking straight up or down: a quarter of the poses
    // look straight up and a quarter straight down, to check this one's is not; half in between.
    let pitch = match random.below(4) {
        0 => FRAC_PI_2,
        1 => -FRAC_PI_2,
        _ => random.between(-FRAC_PI_2, FRAC_PI_2),
    };
    Camera {
        position: random.point(spread),
        yaw: random.between(-MOST_TURNS * TAU, MOST_TURNS * TAU),
        pitch,
    }
}

/// The primary ray through the centre of pixel (x, y) of the 3D view.
fn primary_ray(camera: &Camera, x: usize, y: usize) -> Ray {
    camera.primary_ray(x as f64 + 0.5, y as f64 + 0.5)
}

/// The share of the light a surface gets even in shadow, as the README gives it.
const AMBIENT: f64 = 0.1;

/// How far a channel may round past the bound it is checked against, far more than it can: N.L of
/// two unit vectors, or a mix of two colours, comes out a few parts in 10^16 off at most.
const ROUNDING_SLACK: f64 = 1e-9;

/// A colour fit to show: every channel a number (not NaN) from 0 to 1, give or take rounding.
fn valid(color: Vec3) -> bool {
    [color.x, color.y, color.z]
        .iter()
        .all(|c| !c.is_nan() && (0.0..=1.0 + ROUNDING_SLACK).contains(c))
}

/// Renders the frame twice and compares: into a fresh buffer, and over one that holds the demo.
/// (That it renders at all checks that no pixel panics.)
fn assert_same_frame_in_any_buffer(scene: &Scene, camera: &Camera, case: &str) {
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
    for x in (0..VIEW).step_by(COLUMN_STRIDE) {
        for y in (0..VIEW).step_by(ROW_STRIDE) {
            let color = scene.trace(primary_ray(camera, x, y), 0);
            assert!(valid(color), "{case}: pixel {x}, {y} is {color:?}");
        }
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

/// Camera poses tried, one a seed; every `SCENE_EVERY`th in a random scene (400 scenes) and the
/// rest in the demo, and every `FRAME_EVERY`th also rendered whole (20 frames: a frame traces
/// 262,144 primary rays, not 72).
const POSES: u64 = 1200;
const SCENE_EVERY: u64 = 3;
const FRAME_EVERY: u64 = 60;

#[test]
fn a_thousand_camera_poses_and_hundreds_of_random_scenes() {
    // (compares) Every FRAME_EVERY-th pose's frame, rendered into two buffers.
    for seed in 1..=POSES {
        let (scene, camera) = random_case(seed, SCENE_EVERY);
        let case = format!("seed {seed}: {camera:?}"); // the seed gives the scene again
        assert_valid_rays(&scene, &camera, &case);
        if seed.is_multiple_of(FRAME_EVERY) {
            assert_same_frame_in_any_buffer(&scene, &camera, &case);
        }
    }
}

/// What the test's own roots say `intersect` must return.
#[derive(Debug)]
enum Expected {
    /// A hit at this t: the nearest root in front of the ray, so a point on the surface.
    Hit(f64),
    Miss,
    /// A root or the discriminant within rounding of 0 (a ray that starts on the surface, grazes
    /// the sphere or runs along the plane): a hit and a miss are both right there.
    TooCloseToCall,
}

/// A value this close to 0 is taken to be 0 give or take rounding, which is far smaller here: the
/// discriminants' terms are under 10^3 (see `RAY_SPREAD`) and round by under 10^-12, and the
/// test's roots and `intersect`'s differ by at most 1.3 × 10^-13 in all the cases.
const NEAR_ZERO: f64 = 1e-9;

fn near_zero(value: f64) -> bool {
    value.abs() < NEAR_ZERO
}

/// The sphere |p - C|² = r² along p(t) = O + tD, D a unit vector: the slide's quadratic with a = 1,
/// b = 2 half_b and half_b = (O - C).D, c = |O - C|² - r², so t = -half_b ± √(half_b² - c). The ray
/// hits at the near root if that is in front of it, else at the far one (it starts inside), and
/// misses if there is no root or both are behind it.
fn expected_sphere_hit(origin: Vec3, unit: Vec3, center: Vec3, radius: f64) -> Expected {
    let oc = origin - center;
    let half_b = oc.dot(unit);
    let discriminant = half_b * half_b - (oc.dot(oc) - radius * radius);
    if near_zero(discriminant) {
        return Expected::TooCloseToCall;
    }
    if discriminant < 0.0 {
        return Expected::Miss;
    }
    let near_root = -half_b - discriminant.sqrt();
    let far_root = -half_b + discriminant.sqrt();
    if near_zero(near_root) || near_zero(far_root) {
        Expected::TooCloseToCall
    } else if near_root > 0.0 {
        Expected::Hit(near_root)
    } else if far_root > 0.0 {
        Expected::Hit(far_root)
    } else {
        Expected::Miss
    }
}

/// The plane p.N + d = 0 along p(t) = O + tD: (O.N + d) + t(D.N) = 0, one root, a hit if it is in
/// front of the ray.
fn expected_plane_hit(origin: Vec3, unit: Vec3, normal: Vec3, offset: f64) -> Expected {
    let slant = unit.dot(normal);
    if near_zero(slant) {
        return Expected::TooCloseToCall;
    }
    let root = -(origin.dot(normal) + offset) / slant;
    if near_zero(root) {
        Expected::TooCloseToCall
    } else if root > 0.0 {
        Expected::Hit(root)
    } else {
        Expected::Miss
    }
}

/// How far the t that `intersect` returns may be from the test's root, as a share of the root (of
/// 1 for roots under 1), as rounding errors are shares of the values rounded. `intersect` may find
/// the roots in another order and so round differently: today the two differ by at most
/// 1.4 × 10^-14 of the root here. And the far root cannot pass for the near one: they are
/// 2√(half_b² - c) > 2√NEAR_ZERO > 6 × 10^-5 apart, and the tolerance is under 3 × 10^-5 there, as a
/// sphere's roots here are under 30 (|O - C| < 26 and r < 4: see `RAY_SPREAD`).
const ROOT_TOLERANCE: f64 = 1e-6;

/// Asserts that `intersect` found what the test's roots say: a hit in front of the ray at the
/// expected t, or no hit.
fn assert_hit(hit: Option<f64>, expected: Expected, case: &str) {
    match expected {
        Expected::Hit(root) => assert!(
            hit.is_some_and(|t| t > 0.0 && (t - root).abs() < ROOT_TOLERANCE * root.max(1.0)),
            "{case}: hit at {hit:?}, expected at t = {root}"
        ),
        Expected::Miss => assert_eq!(hit, None, "{case}"),
        Expected::TooCloseToCall => {}
    }
}

/// Random rays, spheres and planes tried in the hit test.
const HIT_CASES: usize = 20_000;
/// Its rays start within `RAY_SPREAD` of the origin on each axis, its spheres' centres are within
/// `CENTER_SPREAD` and their radii up to `MOST_RADIUS`, its planes pass up to `OFFSET_SPREAD` from
/// the origin: so |O - C| < (10 + 5)√3 < 26 and r < 4, which `NEAR_ZERO` and `ROOT_TOLERANCE`
/// rest on.
const RAY_SPREAD: f64 = 10.0;
const CENTER_SPREAD: f64 = 5.0;
const MOST_RADIUS: f64 = 4.0;
const OFFSET_SPREAD: f64 = 5.0;

#[test]
fn a_hit_is_the_nearest_root_in_front_of_the_ray() {
    // Each hit must be the nearest point of the surface in front of the ray, the smallest positive
    // root of the surface's equation, which the test finds by its own formulas. Rays in any
    // direction, among spheres and planes (sizes above `HIT_CASES`): rays start inside and outside
    // spheres and on either side of planes, which lie ahead of them or behind. With this seed, 555
    // rays hit their sphere (385 at the near root, 170 from inside at the far one), 9,946 hit their
    // plane, and no case is too close to call (counted once by printing; not asserted, as the
    // test's own geometry, not `intersect`, decides these counts).
    let mut random = Random::new(7);
    for case in 0..HIT_CASES {
        let origin = random.point(RAY_SPREAD);
        let direction = random.point(1.0); // any direction: Ray::new normalizes it
        let ray = Ray::new(origin, direction, f64::INFINITY);
        let unit = direction.normalize(); // the ray's D
        let center = random.point(CENTER_SPREAD);
        let radius = random.between(0.0, MOST_RADIUS);
        let normal = random.point(1.0).normalize(); // a direction at random
        let offset = random.between(-OFFSET_SPREAD, OFFSET_SPREAD);
        let sphere = Shape::Sphere { center, radius };
        assert_hit(
            sphere.intersect(&ray),
            expected_sphere_hit(origin, unit, center, radius),
            &format!("case {case}, sphere"),
        );
        let plane = Shape::Plane { normal, offset };
        assert_hit(
            plane.intersect(&ray),
            expected_plane_hit(origin, unit, normal, offset),
            &format!("case {case}, plane"),
        );
    }
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

/// A white floor y = -1: the plane p.N + d = 0 with N = (0, 1, 0) and d = 1.
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
    // (compares) Each odd scene's frame, rendered into two buffers.
    let sky = vec3(0.5, 0.7, 1.0);
    let light = vec3(0.0, 5.0, 0.0);
    let huge = 1e6; // a radius a million times the demo's balls'
    let cases = [
        ("no objects", vec![]),
        ("only a floor", vec![floor()]),
        (
            "radius 0",
            vec![floor(), ball(vec3(0.0, 0.0, -3.0), 0.0, white(0.0))],
        ),
        (
            "huge radius",
            // Its near side 5 ahead of the eye, nearly flat across the view.
            vec![ball(vec3(0.0, 0.0, -huge - 5.0), huge, white(0.0))],
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
        assert_same_frame_in_any_buffer(&scene, &Camera::default(), case);
        assert_valid_rays(&scene, &Camera::default(), case);
    }
    // Rays aimed straight at the centres of radius-0 spheres pass them: p² rounds to about 0,
    // either side of it, and such a sphere has no surface to hit (its normal would be (p - C) / 0).
    let mut random = Random::new(5);
    for _ in 0..1000 {
        let center = random.point(5.0); // a thousand centres within 5 of the origin on each axis
        let speck = Scene {
            objects: vec![ball(center, 0.0, white(0.0))],
            light,
            sky,
        };
        let color = speck.trace(Ray::new(vec3(0.0, 0.0, 0.0), center, f64::INFINITY), 0);
        assert_eq!(
            [color.x, color.y, color.z],
            [sky.x, sky.y, sky.z],
            "{center:?}"
        );
    }
    // A ray that grazes the floor and meets it some 10^19 units out, where floor(x) + floor(z) is
    // past the whole numbers an i64 holds and a float has no odd ones: a valid colour, the floor's.
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
    assert!(valid(color), "{color:?}");
    assert_ne!(color, sky, "the floor, not the sky");
    // An empty scene renders the sky in every pixel of the 3D view.
    let empty = Scene {
        objects: vec![],
        light,
        sky,
    };
    let mut frame = vec![0; WIDTH * VIEW];
    render(&empty, &Camera::default(), &mut frame);
    let byte = |channel: f64| (channel * 255.0) as u32; // 0RGB, each channel 0 to 255
    let sky_pixel = byte(sky.x) << 16 | byte(sky.y) << 8 | byte(sky.z);
    for y in 0..VIEW {
        for x in 0..VIEW {
            assert_eq!(frame[y * WIDTH + x], sky_pixel, "pixel {x}, {y}");
        }
    }
}

#[test]
fn a_light_inside_a_sphere_leaves_everything_else_in_shadow() {
    // The light at the centre of a white matte ball: the floor and the ball's outside get only
    // the ambient share, AMBIENT × 1 on a white surface.
    let lamp_center = vec3(0.0, 2.0, -3.0);
    let lamp = ball(lamp_center, 0.5, white(0.0));
    let scene = Scene {
        objects: vec![floor(), lamp],
        light: lamp_center,
        sky: vec3(0.0, 0.0, 0.0),
    };
    let camera = Camera::default();
    let every = 8; // every 8th pixel across and down: 64 x 64 rays
    for y in (0..VIEW).step_by(every) {
        for x in (0..VIEW).step_by(every) {
            let color = scene.trace(primary_ray(&camera, x, y), 0);
            assert!(
                color.x <= AMBIENT + ROUNDING_SLACK,
                "pixel {x}, {y} is lit: {color:?}"
            );
        }
    }
}

#[test]
fn facing_mirrors_stop_at_the_maximum_depth() {
    // A red mirror floor at y = -1 and a blue mirror ceiling at y = 1, both perfect mirrors, lit
    // from between them. A ray that bounces between them forever brings back the colour of the
    // surface where the recursion stops, lit as that surface is lit there: bounce 0 is the floor,
    // so an odd MAX_DEPTH ends on the ceiling and an even one on the floor.
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
    // Steeply down: it meets the floor first, then the two in turn, 0.2 further along -z each time.
    let ray = Ray::new(vec3(0.0, 0.0, 0.0), vec3(0.0, -1.0, -0.1), f64::INFINITY);
    let color = scene.trace(ray, 0);
    assert!(valid(color), "{color:?}");
    let ends_on_ceiling = MAX_DEPTH % 2 == 1;
    assert_eq!(color.x == 0.0, ends_on_ceiling, "{color:?}");
    assert_eq!(color.z == 0.0, !ends_on_ceiling, "{color:?}");
    // Bounce k is at z = -0.1 - 0.2k: how brightly the light lights that point pins the depth.
    let last = f64::from(MAX_DEPTH);
    let (height, normal) = if ends_on_ceiling {
        (1.0, vec3(0.0, -1.0, 0.0))
    } else {
        (-1.0, vec3(0.0, 1.0, 0.0))
    };
    let point = vec3(0.0, height, -0.1 - 0.2 * last);
    let n_dot_l = normal.dot((scene.light - point).normalize());
    let brightness = AMBIENT + (1.0 - AMBIENT) * n_dot_l;
    let shown = if ends_on_ceiling { color.z } else { color.x };
    // Each bounce starts lifted 10^-6 or so off its mirror, which moves the last point a little:
    // 2 × 10^-7 off today, where stopping a bounce or two early would be 0.06 or more off.
    let lift_slack = 1e-5;
    assert!(
        (shown - brightness).abs() < lift_slack,
        "{shown}, not {brightness}"
    );
}

/// Runs the program with `display` as DISPLAY (none if `None`) and returns (status, stdout, stderr).
fn run(display: Option<&str>, args: &[&str]) -> (Option<i32>, String, String) {
    let mut command = Command::new(env!("CARGO_BIN_EXE_raytracer"));
    command.args(args).env_remove("WAYLAND_DISPLAY");
    match display {
        Some(display) => command.env("DISPLAY", display),
        None => command.env_remove("DISPLAY"),
    };
    let output = command.output().expect("the program runs");
    let text = |bytes: Vec<u8>| String::from_utf8(bytes).unwrap();
    (
        output.status.code(),
        text(output.stdout),
        text(output.stderr),
    )
}

/// What the one line says when DISPLAY is not set.
const NOT_SET: &str = "DISPLAY is not set";

#[test]
fn with_no_display_it_says_so_in_one_line_and_ignores_arguments() {
    for args in [&[][..], &["--help"], &["scene.txt", "2"]] {
        let (status, stdout, stderr) = run(None, args);
        assert_eq!(status, Some(1), "{args:?}: {stderr}");
        assert_eq!(stderr.lines().count(), 1, "{args:?}: {stderr}");
        // The line says what failed, opening the window, and what to check: DISPLAY.
        assert!(stderr.contains("cannot open the window"), "{stderr}");
        assert!(stderr.contains(NOT_SET), "{stderr}");
        assert!(stdout.is_empty(), "stdout: {stdout}");
    }
    // DISPLAY set, to a display no X server serves: the same failure, and not the DISPLAY hint.
    let (status, _, stderr) = run(Some(":4711"), &[]);
    assert_eq!(status, Some(1), "{stderr}");
    assert_eq!(stderr.lines().count(), 1, "{stderr}");
    assert!(stderr.contains("cannot open the window"), "{stderr}");
    assert!(!stderr.contains(NOT_SET), "{stderr}");
}

#[test]
fn cameras_on_surfaces_and_far_away_render_valid_frames() {
    // (compares) Each pose's frame, rendered into two buffers.
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
        assert_same_frame_in_any_buffer(&scene, &camera, case);
        assert_valid_rays(&scene, &camera, case);
    }
}

/// A unit vector at right angles to the unit vector `n`.
fn perpendicular(n: Vec3, random: &mut Random) -> Vec3 {
    let any = random.point(1.0);
    (any - n * any.dot(n)).normalize()
}

/// The first few failures that a failing test's message shows.
const FAILURES_SHOWN: usize = 5;

/// Grazing rays tried in the far-away test.
const GRAZING_CASES: usize = 20_000;
/// How far from 1 a fully lit white surface may come out: rounding moves the hit point along the
/// plane, which tilts L off N and takes up to 1.3 × 10^-8 off the colour here. A shadow ray that
/// hit the plane it leaves would give AMBIENT, 0.1.
const FULLY_LIT_TOLERANCE: f64 = 1e-3;

#[test]
fn far_away_a_ray_leaving_a_plane_does_not_hit_it_again() {
    // A plane p.N + d = 0 tilted at random, the origin d from it on N's side, and a ray from the
    // origin that grazes it 10^4 to 10^11 units away. The mirror ray leaves the plane, which is
    // alone in the scene, so it brings back the sky; the shadow ray to a light high above that
    // point reaches it.
    let mut random = Random::new(11);
    let sky = vec3(1.0, 1.0, 1.0);
    let mut failures = Vec::new();
    for case in 0..GRAZING_CASES {
        let normal = random.point(1.0).normalize(); // a direction at random
        let offset = random.between(1.0, 5.0); // d: the origin 1 to 5 units from the plane
        let far = 10f64.powf(random.between(4.0, 11.0)); // 10^4 to 10^11
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
        let mirror_sees_sky = mirrored.x == 0.5 * sky.x; // the half-mirror's half of the sky
        let fully_lit = (lit.x - 1.0).abs() < FULLY_LIT_TOLERANCE;
        if !mirror_sees_sky || !fully_lit {
            let seen = format!("mirror {}, lit {}", mirrored.x, lit.x);
            failures.push(format!("case {case}, {far:.1e} out: {seen}"));
        }
    }
    assert!(
        failures.is_empty(),
        "{} of {GRAZING_CASES}: {:?}",
        failures.len(),
        &failures[..failures.len().min(FAILURES_SHOWN)]
    );
}
