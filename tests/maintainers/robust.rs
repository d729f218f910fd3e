//! Any camera, any scene: every colour a number from 0 to 1, every frame whole, every hit the
//! nearest root, also far from the origin where rounding grows.
#![allow(dead_code, clippy::needless_update)] // each test file uses only part of the program
include!("../../src/main.rs"); // the program itself: its items in reach with no `pub`
include!("../assignment/support.rs"); // the assignment's scenes, cameras and frames, in DVec3
#[path = "support/random.rs"]
mod random;

use random::Random;

/// How far a channel may come out past 1 by rounding: a mix of two colours, or N.L of two unit
/// vectors, is a few parts in 10^16 off at most.
const ROUNDING: f64 = 1e-9;

/// A colour fit to show: every channel a number (not NaN) from 0 to 1, give or take rounding.
fn valid(color: Vec3) -> bool {
    [color.x, color.y, color.z]
        .iter()
        .all(|c| !c.is_nan() && (0.0..=1.0 + ROUNDING).contains(c))
}

/// A camera's pose in words, for a failure message.
fn described(pose: &Camera) -> String {
    let Camera { yaw, pitch, .. } = *pose;
    let eye = to_dvec3(pose.position);
    format!("the eye at {eye} turned {yaw:.3} and tilted {pitch:.3} radians")
}

/// The pixels whose rays are traced from each pose: 8 x 9 of them at a VIEW of 512, on prime
/// strides so that they do not line up with the checkerboard or the map.
fn sample_pixels() -> impl Iterator<Item = (usize, usize)> {
    (0..VIEW)
        .step_by(73)
        .flat_map(|x| (0..VIEW).step_by(61).map(move |y| (x, y)))
}

fn assert_valid_rays(scene: &Scene, pose: &Camera, case: &str) {
    for (x, y) in sample_pixels() {
        let ray = pose.primary_ray(x as f64 + 0.5, y as f64 + 0.5);
        let color = scene.trace(ray, 0);
        assert!(
            valid(color),
            "{case}: pixel {x}, {y} is not a colour from 0 to 1: {}",
            to_dvec3(color)
        );
    }
}

/// A scene's objects and its light, as support.rs's `scene` and `rendered` take them.
type Objects = Vec<(Primitive, Material)>;

/// A scene like the demo's, but the tests' own: the checkered floor, a mirror ball, three matte
/// balls and the light up to the left.
fn demo_like() -> (Objects, DVec3) {
    let objects = vec![
        checkered_floor(),
        ball(dvec3(0.3, 0.0, -4.5), 1.0, WHITE, 0.85),
        ball(dvec3(-2.0, -0.2, -4.2), 0.8, RED, 0.0),
        ball(dvec3(1.9, -0.4, -3.4), 0.6, dvec3(0.0, 1.0, 0.0), 0.0), // green
        ball(dvec3(-0.9, -0.45, -2.6), 0.55, dvec3(0.2, 0.4, 0.9), 0.0), // blue
    ];
    (objects, dvec3(-3.0, 5.0, 1.0))
}

/// The share of spheres among a random scene's objects; the rest are planes.
const SPHERE_SHARE: f64 = 0.7;

/// A random scene of up to 4 spheres and planes: spheres of radius 0.01 to one so big that the
/// cameras are inside it, perfect and part mirrors, the light among them.
fn random_scene(random: &mut Random) -> (Objects, DVec3) {
    let count = random.pick(&[0, 1, 2, 3, 4]);
    let objects = (0..count)
        .map(|_| {
            let primitive = if random.next() < SPHERE_SHARE {
                Primitive::Sphere {
                    center: to_vec3(random.point(5.0)),
                    radius: random.pick(&[0.01, 1.0, 3.0, 1e3]),
                }
            } else {
                Primitive::Plane {
                    normal: to_vec3(random.point(1.0).normalize()),
                    offset: random.between(-3.0, 3.0),
                }
            };
            let color = dvec3(random.next(), random.next(), random.next());
            let part_mirror = random.next();
            let reflectivity = random.pick(&[0.0, part_mirror, 1.0]);
            let checkered = random.next() < 0.5; // half of them
            object(primitive, color, reflectivity, checkered)
        })
        .collect();
    (objects, random.point(6.0))
}

/// A random pose: mostly among the objects, a tenth of them thousands of units away; looking
/// straight up or down a quarter of the time each; turned up to three times round either way.
fn random_camera(random: &mut Random) -> Camera {
    let spread = if random.next() < 0.1 { 1e4 } else { 6.0 };
    let tilted = random.between(-FRAC_PI_2, FRAC_PI_2);
    let pitch = random.pick(&[FRAC_PI_2, -FRAC_PI_2, tilted, tilted]);
    camera_at(
        random.point(spread),
        random.between(-3.0 * TAU, 3.0 * TAU),
        pitch,
    )
}

/// The random scene and pose of a seed, the same each time.
fn random_case(seed: u64) -> (Objects, DVec3, Camera) {
    let mut random = Random::new(seed);
    let (objects, light) = random_scene(&mut random);
    (objects, light, random_camera(&mut random))
}

#[test]
#[ignore = "the maintainers' robustness checks, slower: run with --include-ignored"]
fn any_camera_pose_gives_colours_from_0_to_1() {
    // 300 poses, half in the demo-like scene and half in a random scene each.
    for seed in 0..300 {
        let mut random = Random::new(seed);
        let (objects, light) = if seed % 2 == 0 {
            demo_like()
        } else {
            random_scene(&mut random)
        };
        let pose = random_camera(&mut random);
        let case = format!("seed {seed}, {}", described(&pose));
        assert_valid_rays(&scene(objects, light), &pose, &case);
    }
}

#[test]
#[ignore = "the maintainers' robustness checks, slower: run with --include-ignored"]
fn the_demo_renders_from_any_pose_with_no_panic_and_no_nan() {
    // Whatever is in the demo's scene, yours too: a whole frame from a few poses (its objects and
    // light, under the tests' sky), and rays from many more, each colour a number (above 1 is
    // allowed: a colour may be brighter than white).
    let demo = Scene::demo();
    for seed in 0..100 {
        let pose = random_camera(&mut Random::new(seed));
        if seed < 5 {
            rendered(Scene::demo().objects, to_dvec3(demo.light), pose);
        }
        for (x, y) in sample_pixels() {
            let color = demo.trace(pose.primary_ray(x as f64 + 0.5, y as f64 + 0.5), 0);
            let numbers = !(color.x.is_nan() || color.y.is_nan() || color.z.is_nan());
            assert!(
                numbers,
                "the demo, seed {seed}, pixel {x}, {y}: every channel should be a number, not \
                 {} from {}",
                to_dvec3(color),
                described(&pose)
            );
        }
    }
}

#[test]
#[ignore = "the maintainers' robustness checks, slower: run with --include-ignored"]
fn a_frame_is_the_same_whatever_the_buffer_held_before() {
    // A frame rendered into a buffer of white (support.rs's `frame`) and into one holding another
    // frame: render draws every pixel anew, both halves.
    let (objects, light) = demo_like();
    let other = rendered(objects, light, camera_at(dvec3(1.0, 0.0, 2.0), 0.5, -0.2));
    for seed in 0..6 {
        let (objects, light, pose) = random_case(seed);
        let on_white = rendered(objects, light, pose);
        let (objects, light, pose) = random_case(seed);
        let mut on_other = other.clone();
        render(&scene(objects, light), &pose, &mut on_other);
        let differing = on_white.iter().zip(&on_other).filter(|(a, b)| a != b);
        let count = differing.count();
        assert!(
            count == 0,
            "seed {seed}: the frame rendered over another shows some of it: {count} pixels differ \
             from the same frame rendered over white (look at render and draw_slice, which should \
             draw every pixel of both halves)"
        );
    }
}

/// What the test's own roots say `intersect` must find.
#[derive(Debug)]
enum Expected {
    Hit(f64),
    Miss,
    /// A root within rounding of 0, or a ray grazing the sphere or along the plane: both a hit
    /// and a miss are right.
    TooCloseToCall,
}

/// A value this close to 0 is 0 give or take rounding: the terms here are under 10^3 and round
/// by under 10^-12.
const NEAR_ZERO: f64 = 1e-9;

/// The sphere |O + tD - C|² = r² as a quadratic in t, D a unit vector: a = 1, b = 2 half_b with
/// half_b = (O - C).D, c = |O - C|² - r², so t = -half_b ± √(half_b² - c) (the textbook's formula
/// with b halved, a check apart from the slide's c, q, p² test). The near root if it is in front,
/// else the far one (the ray starts inside).
fn expected_sphere_hit(origin: DVec3, unit: DVec3, center: DVec3, radius: f64) -> Expected {
    let oc = origin - center;
    let half_b = oc.dot(unit);
    let discriminant = half_b * half_b - (oc.dot(oc) - radius * radius);
    if discriminant.abs() < NEAR_ZERO {
        return Expected::TooCloseToCall;
    }
    if discriminant < 0.0 {
        return Expected::Miss;
    }
    let near = -half_b - discriminant.sqrt();
    let far = -half_b + discriminant.sqrt();
    if near.abs() < NEAR_ZERO || far.abs() < NEAR_ZERO {
        Expected::TooCloseToCall
    } else if near > 0.0 {
        Expected::Hit(near)
    } else if far > 0.0 {
        Expected::Hit(far)
    } else {
        Expected::Miss
    }
}

/// The plane (O + tD).N + d = 0: one root, t = -(O.N + d) / (D.N), a hit if it is in front.
fn expected_plane_hit(origin: DVec3, unit: DVec3, normal: DVec3, offset: f64) -> Expected {
    let slant = unit.dot(normal);
    let root = -(origin.dot(normal) + offset) / slant;
    if slant.abs() < NEAR_ZERO || root.abs() < NEAR_ZERO {
        Expected::TooCloseToCall
    } else if root > 0.0 {
        Expected::Hit(root)
    } else {
        Expected::Miss
    }
}

const ROOT_SLACK: f64 = 1e-6;

fn assert_hit(found: Option<f64>, expected: Expected, case: &str) {
    match expected {
        // Rounding moves a root by far less than ROOT_SLACK of it (or of 1); the near and far
        // roots are at least 6 x 10^-5 apart here, so the wrong one fails.
        Expected::Hit(root) => assert!(
            found.is_some_and(|t| (t - root).abs() < ROOT_SLACK * root.max(1.0)),
            "{case}: the nearest hit in front is at t = {root}, intersect found {found:?}"
        ),
        Expected::Miss => assert_eq!(found, None, "{case}: the ray misses, intersect found a hit"),
        Expected::TooCloseToCall => {}
    }
}

/// The program's ray from `origin` along `direction`, unbounded.
fn ray_from(origin: DVec3, direction: DVec3) -> Ray {
    Ray::new(to_vec3(origin), to_vec3(direction), f64::INFINITY)
}

#[test]
#[ignore = "the maintainers' robustness checks, slower: run with --include-ignored"]
fn a_hit_is_the_nearest_root_in_front_of_the_ray() {
    // Rays aimed at or near a sphere, a third of them from inside it, and any plane: three in
    // five rays hit their sphere, a third of all from inside at the far root.
    let mut random = Random::new(7);
    for case in 0..3000 {
        let center = random.point(5.0);
        let radius = random.between(0.0, 4.0);
        let origin = if case % 3 == 0 {
            center + random.point(radius / 2.0)
        } else {
            random.point(10.0)
        };
        let direction = center + random.point(radius * 1.5) - origin;
        let unit = direction.normalize();
        let ray = ray_from(origin, direction);
        let sphere = Primitive::Sphere {
            center: to_vec3(center),
            radius,
        };
        let sphere_root = expected_sphere_hit(origin, unit, center, radius);
        assert_hit(
            sphere.intersect(&ray),
            sphere_root,
            &format!("case {case}, a sphere"),
        );
        let normal = random.point(1.0).normalize();
        let offset = random.between(-5.0, 5.0);
        let plane = Primitive::Plane {
            normal: to_vec3(normal),
            offset,
        };
        let plane_root = expected_plane_hit(origin, unit, normal, offset);
        assert_hit(
            plane.intersect(&ray),
            plane_root,
            &format!("case {case}, a plane"),
        );
    }
}

#[test]
#[ignore = "the maintainers' robustness checks, slower: run with --include-ignored"]
fn odd_scenes_give_colours_from_0_to_1() {
    let light = dvec3(0.0, 5.0, 0.0);
    let huge = 1e3; // a radius a thousand times the demo's balls'
    let cases = [
        ("no objects", vec![]),
        ("only a floor", vec![checkered_floor()]),
        (
            "a huge sphere, its near side 5 ahead",
            vec![ball(dvec3(0.0, 0.0, -huge - 5.0), huge, WHITE, 0.0)],
        ),
        (
            "two spheres in the same place",
            vec![
                ball(dvec3(0.0, 0.0, -3.0), 1.0, WHITE, 0.5),
                ball(dvec3(0.0, 0.0, -3.0), 1.0, WHITE, 0.5),
            ],
        ),
    ];
    for (case, objects) in cases {
        assert_valid_rays(&scene(objects, light), &Camera::default(), case);
    }
}

/// The slide's checkerboard with floor, as the README gives it: is the unit square under this
/// floor point an odd one?
fn on_an_odd_square(point: DVec3) -> bool {
    ((point.x.floor() as i64 + point.z.floor() as i64) & 1) == 1
}

/// How far a far floor point's colour may be off: N.L there adds under 10^-5.
const FAR_SLACK: f64 = 1e-4;

#[test]
#[ignore = "the maintainers' robustness checks, slower: run with --include-ignored"]
fn a_floor_hit_far_out_at_the_horizon_shows_its_square_in_the_ambient_light() {
    // Rays that meet the floor (y = -1) 10^6 to 10^12 units out, as the pixels next to the horizon
    // do: the light, 5 units up, meets the floor there almost edge on (N.L under 10^-5), so each
    // shows its square's share of the ambient light, whatever rounding does that far out.
    let far_floor = scene(vec![checkered_floor()], dvec3(0.0, 5.0, 0.0));
    let mut random = Random::new(13);
    for case in 0..300 {
        let far = 10f64.powf(random.between(6.0, 12.0));
        let angle = random.between(0.0, TAU);
        let on_floor = dvec3(far * angle.cos(), -1.0, far * angle.sin());
        let color = to_dvec3(far_floor.trace(ray_from(ORIGIN, on_floor), 0));
        let square = if on_an_odd_square(on_floor) {
            README_ODD_SQUARE_BRIGHTNESS
        } else {
            1.0
        };
        let expected = WHITE * README_AMBIENT * square;
        assert!(
            (color - expected).length() < FAR_SLACK,
            "case {case}: the floor {far:.1e} units out should show {expected}, its square in the \
             ambient light, not {color}. This holds src/main.rs to the README's ambient \
             {README_AMBIENT} and odd squares {README_ODD_SQUARE_BRIGHTNESS} as bright \
             (README_AMBIENT, README_ODD_SQUARE_BRIGHTNESS in tests/assignment/support.rs): if \
             you changed one on purpose, change it there too; if not, look at trace and odd_square"
        );
    }
}

#[test]
#[ignore = "the maintainers' robustness checks, slower: run with --include-ignored"]
fn cameras_on_surfaces_and_far_away_give_colours_from_0_to_1() {
    let (objects, light) = demo_like();
    let demo = scene(objects, light);
    for (case, position, yaw, pitch) in [
        ("on the floor", dvec3(0.0, -1.0, -1.0), 0.0, -0.5),
        (
            "on top of the mirror ball",
            dvec3(0.3, 1.0, -4.5),
            1.0,
            -1.2,
        ),
        ("below the floor", dvec3(0.0, -5.0, 0.0), 0.0, 0.3),
        ("10,000 units away", dvec3(0.0, 0.0, 1e4), 0.0, 0.0),
        ("straight up, turned past 2 pi", ORIGIN, 7.0, FRAC_PI_2),
    ] {
        assert_valid_rays(&demo, &camera_at(position, yaw, pitch), case);
    }
}

/// How near 1 a fully lit white surface must come out: rounding tilts L off N by far less, and a
/// shadow ray that hit the plane it leaves would give README_AMBIENT, 0.1.
const FULLY_LIT: f64 = 1e-3;

#[test]
#[ignore = "the maintainers' robustness checks, slower: run with --include-ignored"]
fn a_ray_leaving_a_plane_far_out_does_not_hit_it_again() {
    // A plane tilted at random, 1 to 5 units from the origin, and a ray from the origin that meets
    // it 10 to 10^6 units away, as a floor is met out to the horizon.
    // Alone in the scene, the plane as a black half mirror shows half the sky (its mirror ray
    // leaves it), and as a white matte surface under a light straight above, it is fully lit
    // (its shadow ray leaves it; hitting it again would give README_AMBIENT, 0.1).
    let sky = WHITE;
    let mut random = Random::new(11);
    for case in 0..3000 {
        let normal = random.point(1.0).normalize();
        let offset = random.between(1.0, 5.0);
        let far = 10f64.powf(random.between(1.0, 6.0));
        let any = random.point(1.0);
        let along = (any - normal * any.dot(normal)).normalize(); // a direction in the plane
        let on_plane = normal * -offset + along * far;
        let plane = || Primitive::Plane {
            normal: to_vec3(normal),
            offset,
        };
        let black_half_mirror = object(plane(), DVec3::ZERO, 0.5, false);
        let mut mirror_scene = scene(vec![black_half_mirror], ORIGIN);
        mirror_scene.sky = to_vec3(sky);
        let mirrored = mirror_scene.trace(ray_from(ORIGIN, on_plane), 0);
        let white_matte = object(plane(), WHITE, 0.0, false);
        let lit_scene = scene(vec![white_matte], on_plane + normal * far);
        let lit = lit_scene.trace(ray_from(ORIGIN, on_plane), 0);
        assert!(
            mirrored.x == 0.5 * sky.x,
            "case {case}, {far:.1e} out: the mirror ray hit the plane it left: the black half \
             mirror shows {}, not half the white sky",
            to_dvec3(mirrored)
        );
        assert!(
            (lit.x - 1.0).abs() < FULLY_LIT,
            "case {case}, {far:.1e} out: the shadow ray hit the plane it left: the white plane \
             shows {}, not fully lit (1, 1, 1)",
            to_dvec3(lit)
        );
    }
}
