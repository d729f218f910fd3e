//! The 3D view, the assignment's steps 1 to 6, 8 and 9: camera, intersections, shading, shadows,
//! the checkerboard and reflections, each checked where the test works out itself: on a pixel, or
//! along a ray it traces.
#![allow(dead_code)] // each test file uses only part of the program
include!("../src/main.rs"); // the program itself: its items in reach with no `pub`
#[path = "support/scenes.rs"]
mod scenes;

use scenes::*;
use std::f64::consts::FRAC_1_SQRT_2;

/// A pixel counts as red where its red byte is over this many times its green and its blue: a
/// RED ball shows 9 times, however lit; the sky and the floor never more than once.
const RED_OVER: u32 = 2;

fn is_red([r, g, b]: [u32; 3]) -> bool {
    r > RED_OVER * g && r > RED_OVER * b
}

/// Whole frames are checked on every `EVERY`th pixel each way: enough to meet every part of a
/// surface, a 50th of the work.
const EVERY: usize = 7;

/// The tests shade the very point a pixel's centre sees, as the program does: only rounding may
/// tip a byte over.
const SHADING_SLACK: u32 = 1;

#[test]
fn pixels_that_hit_nothing_show_the_sky() {
    let ball = v3(0.0, 0.0, -4.0);
    let scene = scene_of(vec![sphere(ball, 1.0, matte(RED))], v3(0.0, 5.0, 0.0));
    let camera = Camera::default();
    let frame = frame_of(&scene, &camera);
    let last = VIEW - 1;
    let above_the_ball = project(&camera, ball + v3(0.0, 2.0, 0.0));
    for pixel in [(0, 0), (last, 0), (0, last), (last, last), above_the_ball] {
        let seen = rgb(&frame, pixel);
        assert!(
            seen == bytes(SKY),
            "pixel {pixel:?} should show the sky, not RGB {seen:?}. {}",
            holds(&[SCREEN_FIGURE])
        );
    }
}

#[test]
fn a_sphere_covers_its_projected_centre_and_ends_at_its_silhouette() {
    let center = v3(1.0, 0.5, -5.0);
    let radius = 1.0;
    let scene = scene_of(vec![sphere(center, radius, matte(RED))], v3(0.0, 0.0, 0.0));
    let camera = Camera::default();
    let frame = frame_of(&scene, &camera);
    let middle = rgb(&frame, project(&camera, center));
    assert!(
        is_red(middle),
        "the sphere's centre shows RGB {middle:?}, not the red sphere. {}",
        holds(&[SCREEN_FIGURE])
    );
    // Seen from the eye the sphere fills a cone of half-angle asin(r / distance): MARGIN inside
    // it, beside the centre, is the sphere, and MARGIN past it is sky.
    const MARGIN: f64 = 0.02; // radians, 5 pixels at a VIEW of 512
    let distance = center.length();
    let silhouette = (radius / distance).asin();
    let toward = center.normalize();
    let beside = v3(toward.z, 0.0, -toward.x).normalize(); // level, at right angles to `toward`
    let at = |angle: f64| {
        project(
            &camera,
            (toward * angle.cos() + beside * angle.sin()) * distance,
        )
    };
    let inside = rgb(&frame, at(silhouette - MARGIN));
    assert!(
        is_red(inside),
        "just inside the silhouette should be the red sphere, not RGB {inside:?}. {}",
        holds(&[SCREEN_FIGURE])
    );
    let outside = rgb(&frame, at(silhouette + MARGIN));
    assert!(
        outside == bytes(SKY),
        "just past the silhouette should be sky, not RGB {outside:?}. {}",
        holds(&[SCREEN_FIGURE])
    );
}

#[test]
fn the_nearest_of_two_spheres_in_line_hides_the_other() {
    // A red sphere in front of a green one, listed first and then last: the nearer wins whatever
    // the list's order.
    let near = || sphere(v3(0.0, 0.0, -3.0), 0.5, matte(RED));
    let far = || sphere(v3(0.0, 0.0, -6.0), 1.5, matte(PURE_GREEN));
    for (order, objects) in [
        ("first", vec![near(), far()]),
        ("last", vec![far(), near()]),
    ] {
        let frame = frame_of(&scene_of(objects, v3(0.0, 0.0, 0.0)), &Camera::default());
        let middle = rgb(&frame, (VIEW / 2, VIEW / 2));
        assert!(
            is_red(middle),
            "with the nearer, red sphere listed {order}, the middle shows RGB {middle:?}, not red"
        );
    }
}

#[test]
fn a_sphere_is_shaded_ambient_plus_n_dot_l() {
    let center = v3(0.0, 0.0, -4.0);
    let light = v3(-10.0, 0.0, -4.0);
    let scene = scene_of(vec![sphere(center, 1.0, matte(RED))], light);
    let camera = Camera::default();
    let frame = frame_of(&scene, &camera);
    // Two points on the sphere's front: on the left facing the light, on the right facing away.
    for (side, normal) in [
        (
            "the side facing the light",
            v3(-FRAC_1_SQRT_2, 0.0, FRAC_1_SQRT_2),
        ),
        (
            "the side facing away",
            v3(FRAC_1_SQRT_2, 0.0, FRAC_1_SQRT_2),
        ),
    ] {
        let pixel = project(&camera, center + normal);
        let direction = pixel_direction(&camera, pixel);
        let point = ray_sphere(eye(&camera), direction, center, 1.0).expect("a ray to the ball");
        let red = rgb(&frame, pixel)[0];
        let expected = byte(RED.x * lit_share(point, point - center, light));
        assert!(
            red.abs_diff(expected) <= SHADING_SLACK,
            "{side}: red {red}, where ambient + (1 - ambient) N.L gives {expected}. {}",
            holds(&[AMBIENT_FIGURE, SCREEN_FIGURE])
        );
    }
}

#[test]
fn a_sphere_between_the_floor_and_the_light_casts_a_shadow() {
    let center = v3(0.0, 0.0, -5.0);
    let light = v3(0.0, 3.0, -5.0);
    let scene = scene_of(
        vec![checkered_floor(), sphere(center, 1.0, matte(RED))],
        light,
    );
    let camera = camera_at(v3(0.0, 1.0, 0.0), 0.0, -0.3);
    let frame = frame_of(&scene, &camera);
    // Two floor points in view: the segment from the first to the light passes the sphere's
    // centre 0.69 away, inside it; the second's passes 1.65 away. Each shows its square's share.
    let shaded = project(&camera, v3(-0.5, FLOOR_Y, -4.2));
    let lit = project(&camera, v3(-2.5, FLOOR_Y, -4.2));
    let up = v3(0.0, 1.0, 0.0);
    for (what, pixel, light_share) in [
        ("in the shadow, ambient only", shaded, README_AMBIENT),
        (
            "beside the shadow, lit",
            lit,
            lit_share(floor_seen(&camera, lit), up, light),
        ),
    ] {
        let green = rgb(&frame, pixel)[1];
        let expected = byte(WHITE.y * light_share * square_share(floor_seen(&camera, pixel)));
        assert!(
            green.abs_diff(expected) <= SHADING_SLACK,
            "the floor {what}: green {green}, expected {expected}. {}",
            holds(&[
                AMBIENT_FIGURE,
                SQUARE_FIGURE,
                ODD_SQUARE_FIGURE,
                SCREEN_FIGURE
            ])
        );
    }
}

#[test]
fn only_what_lies_between_a_point_and_the_light_shades_it() {
    // (compares) A floor point with two balls that do not lie between it and the light, one
    // beyond the light and one beside it, is as bright as with no balls at all.
    let light = v3(0.0, 2.0, -4.0);
    let beyond = sphere(v3(0.0, 4.0, -4.0), 1.0, matte(RED));
    let beside = sphere(v3(4.0, 0.0, -8.0), 1.0, matte(RED));
    let camera = camera_at(v3(0.0, 1.0, 0.0), 0.0, -0.3);
    let alone = frame_of(&scene_of(vec![checkered_floor()], light), &camera);
    let with_balls = frame_of(
        &scene_of(vec![checkered_floor(), beyond, beside], light),
        &camera,
    );
    let pixel = project(&camera, v3(0.5, FLOOR_Y, -3.5));
    let seen = rgb(&with_balls, pixel);
    let expected = rgb(&alone, pixel);
    assert!(
        seen == expected,
        "a ball beyond the light or beside it changed the floor from RGB {expected:?} to {seen:?}"
    );
}

/// A light high above the floor: the squares the floor tests look at, x and z from -2 to 2, get
/// nearly all of it (N.L over 0.999 there).
const HIGH_LIGHT: V3 = v3(0.0, 100.0, 0.0);

/// The checkered floor alone under HIGH_LIGHT, seen from 2 units above it, looking down: the
/// camera and its frame.
fn floor_from_above() -> (Camera, Vec<u32>) {
    let camera = camera_at(v3(0.0, 1.0, 3.0), 0.0, -0.5);
    let frame = frame_of(&scene_of(vec![checkered_floor()], HIGH_LIGHT), &camera);
    (camera, frame)
}

#[test]
fn the_floor_is_checkered_by_floor_x_plus_floor_z() {
    let (camera, frame) = floor_from_above();
    // Square centres on both sides of x = 0 and of z = 0.
    for x in [-1.5, -0.5, 0.5, 1.5] {
        for z in [-1.5, -0.5, 0.5, 1.5] {
            let point = v3(x, FLOOR_Y, z);
            let green = rgb(&frame, project(&camera, point))[1];
            let odd = on_an_odd_square(point);
            assert!(
                is_dark(green, point, HIGH_LIGHT) == odd,
                "the floor at x = {x}, z = {z} is on an {} square: it should look {}, yet shows \
                 green {green}. {}",
                if odd { "odd" } else { "even" },
                if odd { "dark" } else { "bright" },
                holds(&[SQUARE_FIGURE, ODD_SQUARE_FIGURE, SCREEN_FIGURE])
            );
        }
    }
}

#[test]
fn the_floors_odd_squares_show_a_quarter_of_the_light() {
    // Lit from high above, each point shows the lit share of white, on an odd square a quarter
    // of it: README_ODD_SQUARE, the README's figure.
    let (camera, frame) = floor_from_above();
    let up = v3(0.0, 1.0, 0.0);
    for x in [-0.5, 0.5] {
        let pixel = project(&camera, v3(x, FLOOR_Y, -0.5));
        let point = floor_seen(&camera, pixel);
        let odd = on_an_odd_square(point);
        let green = rgb(&frame, pixel)[1];
        let expected = byte(WHITE.y * lit_share(point, up, HIGH_LIGHT) * square_share(point));
        assert!(
            green.abs_diff(expected) <= SHADING_SLACK,
            "the floor at x = {x}, z = -0.5, on an {} square: green {green}, expected {expected}. \
             {}",
            if odd { "odd" } else { "even" },
            holds(&[
                ODD_SQUARE_FIGURE,
                SQUARE_FIGURE,
                AMBIENT_FIGURE,
                SCREEN_FIGURE
            ])
        );
    }
}

/// Floor points this close to a square's edge (in units) are passed over: a pixel's ray, bent by
/// the curved mirror, may land on either square there.
const EDGE_BAND: f64 = 0.05;

/// Where the unit sphere at `center` sends the ray of the default camera's pixel (x, y) when its
/// eye is at `eye`, by the test's own geometry: the hit and R = D - 2(D.N)N, if it hits.
fn reflected_ray(eye: V3, center: V3, (x, y): (usize, usize)) -> Option<(V3, V3)> {
    let d = pixel_direction(&Camera::default(), (x, y)).normalize();
    let point = ray_sphere(eye, d, center, 1.0)?;
    let n = point - center;
    Some((point, d - n * (2.0 * d.dot(n))))
}

/// Does the segment from a to b pass through the sphere?
fn segment_hits_sphere(a: V3, b: V3, center: V3, radius: f64) -> bool {
    let ab = b - a;
    let t = ((center - a).dot(ab) / ab.dot(ab)).clamp(0.0, 1.0);
    let closest = a + ab * t - center;
    closest.dot(closest) < radius * radius
}

#[test]
fn a_mirror_ball_reflects_the_checkered_floor_and_the_sky() {
    let center = v3(0.0, 0.0, -4.0);
    let light = v3(0.0, 20.0, 20.0);
    let perfect_mirror = mirror(WHITE, 1.0);
    let scene = scene_of(
        vec![checkered_floor(), sphere(center, 1.0, perfect_mirror)],
        light,
    );
    let camera = Camera::default();
    let frame = frame_of(&scene, &camera);
    // Every `EVERY`th pixel each way that sees the ball: its mirror ray goes up to the sky, or
    // down to a floor square, which shows bright or dark unless the point is near a square's edge
    // or in the ball's shadow.
    let near_edge = |w: f64| {
        let squares = w / README_SQUARE_SIZE; // from the nearest edge, in squares
        (squares - squares.round()).abs() * README_SQUARE_SIZE < EDGE_BAND
    };
    for y in (0..VIEW).step_by(EVERY) {
        for x in (0..VIEW).step_by(EVERY) {
            let Some((point, direction)) = reflected_ray(eye(&camera), center, (x, y)) else {
                continue;
            };
            let seen = rgb(&frame, (x, y));
            if direction.y >= 0.0 {
                assert!(
                    seen == bytes(SKY),
                    "pixel {x}, {y} should reflect the sky, not RGB {seen:?}: its mirror ray \
                     R = D - 2(D.N)N from the ball at {point:?} goes up"
                );
                continue;
            }
            let on_floor = point + direction * ((FLOOR_Y - point.y) / direction.y);
            if near_edge(on_floor.x) || near_edge(on_floor.z) {
                continue;
            }
            if segment_hits_sphere(on_floor, light, center, 1.0) {
                continue;
            }
            let odd = on_an_odd_square(on_floor);
            assert!(
                is_dark(seen[1], on_floor, light) == odd,
                "pixel {x}, {y} should reflect the floor point {on_floor:?}, on an {} square, \
                 and look {}; it shows RGB {seen:?}. Its mirror ray, R = D - 2(D.N)N from the \
                 ball at {point:?}, is wrong, or the floor's squares are. {}",
                if odd { "odd" } else { "even" },
                if odd { "dark" } else { "bright" },
                holds(&[SQUARE_FIGURE, ODD_SQUARE_FIGURE, SCREEN_FIGURE])
            );
        }
    }
}

#[test]
fn a_part_mirror_mixes_its_own_colour_with_what_its_mirror_ray_sees() {
    // A grey wall z = -5 facing the eye, a quarter mirror, lit from the eye: the middle pixel
    // shows three quarters of the wall's own lit colour and a quarter of what its mirror ray sees
    // going straight back past the eye: the sky.
    let reflectivity = 0.25;
    let grey = v3(0.6, 0.6, 0.6);
    let facing_the_eye = v3(0.0, 0.0, 1.0);
    let wall = Primitive::Plane {
        normal: facing_the_eye.into(),
        offset: 5.0, // p.N + d = z + 5 = 0
    };
    let camera = Camera::default();
    let scene = scene_of(vec![(wall, mirror(grey, reflectivity))], eye(&camera));
    let frame = frame_of(&scene, &camera);
    // The middle pixel's centre sees the wall 0.014 off (0, 0, -5), where N.L is 4 x 10^-6 less.
    let lit = lit_share(v3(0.0, 0.0, -5.0), facing_the_eye, eye(&camera));
    let expected = bytes(grey * (lit * (1.0 - reflectivity)) + SKY * reflectivity);
    let shown = rgb(&frame, (VIEW / 2, VIEW / 2));
    for (channel, name) in ["red", "green", "blue"].iter().enumerate() {
        assert!(
            shown[channel].abs_diff(expected[channel]) <= SHADING_SLACK,
            "{name}: {}, where 3/4 of the lit wall and 1/4 of the sky give {} (RGB {shown:?}). \
             {}",
            shown[channel],
            expected[channel],
            holds(&[AMBIENT_FIGURE])
        );
    }
}

#[test]
fn facing_mirrors_stop_after_the_readmes_five_bounces() {
    // A red mirror floor y = -1 and a blue mirror ceiling y = 1, both perfect mirrors, lit from
    // between them. A ray bouncing between them brings back the colour of the surface where the
    // recursion stops, lit as that point is lit: bounce 0 is the floor, so after an odd number of
    // bounces it ends on the ceiling and after an even one on the floor.
    const CEILING_Y: f64 = 1.0;
    let up = v3(0.0, 1.0, 0.0);
    let down = v3(0.0, -1.0, 0.0);
    let floor = Primitive::Plane {
        normal: up.into(),
        offset: -FLOOR_Y, // y + 1 = 0
    };
    let ceiling = Primitive::Plane {
        normal: down.into(),
        offset: CEILING_Y, // -y + 1 = 0
    };
    let scene = scene_of(
        vec![
            (floor, mirror(PURE_RED, 1.0)),
            (ceiling, mirror(PURE_BLUE, 1.0)),
        ],
        v3(0.0, 0.0, -3.0),
    );
    // Steeply down: bounce k is at z = -0.1 - 0.2k, on the ceiling for odd k. Each bounce's ray
    // starts a hair off its mirror (10^-3 would be a lot), which moves the last point by a few
    // thousandths at most; stopping a bounce early or late changes the brightness by 0.06 or more.
    const BOUNCE_SLACK: f64 = 0.01;
    let ray = ray_from(v3(0.0, 0.0, 0.0), v3(0.0, -1.0, -0.1), f64::INFINITY);
    let color = scene.trace(ray, 0);
    // Bounce k's mirror, its point, and how brightly that point is lit.
    let bounce = |k: u32| {
        let on_ceiling = k % 2 == 1;
        let (mirror, height, normal) = if on_ceiling {
            ("the blue ceiling", CEILING_Y, down)
        } else {
            ("the red floor", FLOOR_Y, up)
        };
        let point = v3(0.0, height, -0.1 - 0.2 * f64::from(k));
        (mirror, point, lit_share(point, normal, scene.light.into()))
    };
    let (last_mirror, last_point, expected) = bounce(README_BOUNCES);
    // Which mirror the colour comes from: only the floor's red, or only the ceiling's blue.
    let (ended_on, shown) = match (color.x > 0.0, color.y > 0.0, color.z > 0.0) {
        (true, false, false) => ("the red floor", color.x),
        (false, false, true) => ("the blue ceiling", color.z),
        _ => ("neither mirror alone", f64::NAN),
    };
    if ended_on == last_mirror && (shown - expected).abs() < BOUNCE_SLACK {
        return;
    }
    let seen_as = (0..=2 * README_BOUNCES)
        .map(bounce)
        .position(|(mirror, _, lit)| mirror == ended_on && (shown - lit).abs() < BOUNCE_SLACK);
    let why = match seen_as {
        Some(k) => format!(
            "it ended on {ended_on} lit {shown:.3}, as bounce {k} is: the recursion stops at \
             another depth than MAX_DEPTH = {README_BOUNCES}, or the mirror ray R = D - 2(D.N)N goes \
             another way (with its sign flipped it turns back into the mirror it leaves)"
        ),
        None if ended_on == last_mirror && (shown - README_AMBIENT).abs() < BOUNCE_SLACK => {
            format!(
                "it ended there, but lit only by the ambient share, {README_AMBIENT}: its shadow ray is \
             blocked, though nothing lies between the point and the light (does the shadow ray \
             stop at the light, t = |L - P|?)"
            )
        }
        None if ended_on == last_mirror => format!(
            "it ended there, but lit {shown:.3}: ambient + (1 - ambient) N.L is worked out wrong \
             at that point"
        ),
        None => format!(
            "it shows the colour {color:?} (red from the floor, blue from the ceiling): a perfect \
             mirror mixes in nothing of its own colour until the last bounce, or the ray left \
             the mirrors for the sky"
        ),
    };
    panic!(
        "A ray between two facing mirrors should end, after {README_BOUNCES} bounces, on {last_mirror} \
         at {last_point:?}, lit {expected:.3}; {why}. {}",
        holds(&[BOUNCES_FIGURE, AMBIENT_FIGURE])
    );
}

#[test]
fn a_colour_brighter_than_white_shows_as_255() {
    // A matte ball of colour (0, 0.3, 2) seen head on, lit from the eye: its blue, about 2 at the
    // middle, shows as 255; unclamped, about 510 would carry into green's byte.
    let glowing = v3(0.0, 0.3, 2.0);
    let camera = Camera::default();
    let scene = scene_of(
        vec![sphere(v3(0.0, 0.0, -4.0), 1.0, matte(glowing))],
        eye(&camera),
    );
    let frame = frame_of(&scene, &camera);
    let [red, green, blue] = rgb(&frame, (VIEW / 2, VIEW / 2));
    // N.L at the middle pixel is within 10^-4 of 1: green 0.3 x 255 = 76.5 shows as 76.
    let expected_green = byte(glowing.y);
    assert!(
        [red, green, blue] == [0, expected_green, 255],
        "blue over 1 should show as 255 and leave green at {expected_green}: shows {:?}",
        [red, green, blue]
    );
}

// The camera: turned, tilted, moved, and in odd places.

/// A red ball and a scene lit from high up, for the camera tests.
fn ball_scene(center: V3) -> Scene {
    scene_of(vec![sphere(center, 0.5, matte(RED))], v3(0.0, 50.0, 0.0))
}

#[test]
fn turning_the_camera_left_brings_a_ball_on_the_left_into_view() {
    let ball = v3(-3.0, 0.0, -1.5); // far to the left of the default view
    let scene = ball_scene(ball);
    let turned = camera_at(v3(0.0, 0.0, 0.0), FRAC_PI_2, 0.0);
    let where_seen = project(&turned, ball);
    let seen = rgb(&frame_of(&scene, &turned), where_seen);
    assert!(
        is_red(seen),
        "turned a quarter left, the red ball should show at {where_seen:?}, not RGB {seen:?}. {}",
        holds(&[SCREEN_FIGURE])
    );
    let ahead = rgb(&frame_of(&scene, &Camera::default()), where_seen);
    assert!(
        !is_red(ahead),
        "not turned, the ball on the left should be out of view, yet {where_seen:?} shows RGB \
             {ahead:?}"
    );
}

#[test]
fn tilting_the_camera_up_brings_a_ball_above_into_view() {
    // The ball is 1.11 radians up from -z; tilted 0.9 up, the camera sees it in the upper half
    // of the view, where an upside-down image would not show it.
    let ball = v3(0.0, 3.0, -1.5);
    let scene = ball_scene(ball);
    let tilted = camera_at(v3(0.0, 0.0, 0.0), 0.0, 0.9);
    let where_seen = project(&tilted, ball);
    let seen = rgb(&frame_of(&scene, &tilted), where_seen);
    assert!(
        is_red(seen),
        "tilted up, the red ball should show at {where_seen:?}, not RGB {seen:?}. {}",
        holds(&[SCREEN_FIGURE])
    );
    let level = rgb(&frame_of(&scene, &Camera::default()), where_seen);
    assert!(
        !is_red(level),
        "not tilted, the ball above should be out of view, yet {where_seen:?} shows RGB {level:?}"
    );
}

#[test]
fn moving_the_camera_moves_the_view() {
    let ball = v3(2.0, 0.5, -4.0);
    let scene = ball_scene(ball);
    let level_with_it = camera_at(v3(2.0, 0.5, 0.0), 0.0, 0.0); // the ball now dead ahead
    let middle = (VIEW / 2, VIEW / 2);
    let seen = rgb(&frame_of(&scene, &level_with_it), middle);
    assert!(
        is_red(seen),
        "moved level with the red ball, the middle should show it, not RGB {seen:?}. {}",
        holds(&[SCREEN_FIGURE])
    );
    let before = rgb(&frame_of(&scene, &Camera::default()), middle);
    assert!(
        !is_red(before),
        "from the start, the middle should not show the ball, yet it shows RGB {before:?}"
    );
}

#[test]
fn a_camera_inside_a_sphere_sees_its_inside() {
    // From the centre of a white mirror ball lit from outside, every ray meets its inside, and the
    // ball's own wall stands between each point of it and the light: each bounce, and so each
    // pixel, shows the ambient share alone. A surface seen from the wrong side would send its
    // mirror rays out to the floor and the sky.
    let center = v3(0.3, 0.0, -4.5);
    let scene = scene_of(
        vec![checkered_floor(), sphere(center, 1.0, mirror(WHITE, 0.85))],
        v3(-3.0, 5.0, 1.0),
    );
    let frame = frame_of(&scene, &camera_at(center, 0.0, 0.0));
    let expected = bytes(WHITE * README_AMBIENT);
    for y in (0..VIEW).step_by(EVERY) {
        for x in (0..VIEW).step_by(EVERY) {
            let seen = rgb(&frame, (x, y));
            assert!(
                seen == expected,
                "from inside the mirror ball, pixel {x}, {y} shows RGB {seen:?}, not the \
                 inside's ambient share, RGB {expected:?}. {}",
                holds(&[AMBIENT_FIGURE])
            );
        }
    }
}

#[test]
fn from_below_the_floor_its_underside_gets_only_ambient_light() {
    let scene = scene_of(vec![checkered_floor()], v3(0.0, 5.0, 0.0));
    let below = camera_at(v3(0.0, -3.0, 0.0), 0.0, 1.0);
    let frame = frame_of(&scene, &below);
    // The light is above the floor: its underside faces away from it.
    let pixel = project(&below, v3(0.5, FLOOR_Y, -1.5));
    let point = floor_seen(&below, pixel);
    let green = rgb(&frame, pixel)[1];
    let expected = byte(WHITE.y * README_AMBIENT * square_share(point));
    assert!(
        green == expected,
        "the floor's underside at {point:?}, on an {} square, should show only the ambient \
         light, green {expected}, not {green}. {}",
        if on_an_odd_square(point) {
            "odd"
        } else {
            "even"
        },
        holds(&[
            AMBIENT_FIGURE,
            SQUARE_FIGURE,
            ODD_SQUARE_FIGURE,
            SCREEN_FIGURE
        ])
    );
}

#[test]
fn looking_straight_down_shows_the_checkered_floor() {
    let light = v3(0.0, 5.0, 0.0);
    let scene = scene_of(vec![checkered_floor()], light);
    let down = camera_at(v3(0.0, 0.0, 0.0), 0.0, -FRAC_PI_2);
    let frame = frame_of(&scene, &down);
    for point in [v3(0.5, FLOOR_Y, 0.5), v3(-0.5, FLOOR_Y, 0.5)] {
        let green = rgb(&frame, project(&down, point))[1];
        let odd = on_an_odd_square(point);
        assert!(
            is_dark(green, point, light) == odd,
            "looking straight down, the floor point {point:?} is on an {} square: it should look \
             {}, yet shows green {green}. {}",
            if odd { "odd" } else { "even" },
            if odd { "dark" } else { "bright" },
            holds(&[SQUARE_FIGURE, ODD_SQUARE_FIGURE, SCREEN_FIGURE])
        );
    }
}

#[test]
fn a_light_inside_a_sphere_leaves_everything_else_in_shadow() {
    // The light at the centre of a white ball: the floor and the ball's outside get only the
    // ambient share of their colour.
    let lamp = v3(0.0, 2.0, -3.0);
    let mut scene = scene_of(
        vec![checkered_floor(), sphere(lamp, 0.5, matte(WHITE))],
        lamp,
    );
    scene.sky = v3(0.0, 0.0, 0.0).into();
    let frame = frame_of(&scene, &Camera::default());
    let most = byte(README_AMBIENT);
    for y in (0..VIEW).step_by(EVERY) {
        for x in (0..VIEW).step_by(EVERY) {
            let [red, ..] = rgb(&frame, (x, y));
            assert!(
                red <= most,
                "pixel {x}, {y} shows red {red}, over the ambient {most}: lit by a light in a \
                 ball. {}",
                holds(&[AMBIENT_FIGURE])
            );
        }
    }
}
