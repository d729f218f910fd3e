//! The 2D slice, the assignment's "for y = 0, visualize every 10th ray": the plane of the screen's
//! middle row seen from above, with the eye, the screen, the light, the balls where the plane cuts
//! them, and every 10th ray of that row with its hit, shadow and mirror rays.
use super::*;

/// Which of the sampled rays is the one just left of the screen's middle.
const NEAR_MIDDLE: usize = VIEW / 2 / README_SAMPLED_EVERY;

#[test]
fn the_eye_its_screens_middle_row_and_the_light_are_drawn_on_the_map_or_its_edge() {
    // From the start: the eye, at (0, 0, 0), a pink square 7 pixels wide, and the screen's middle
    // row a pink line from C - right = (-1, 0, -1) to C + right = (1, 0, -1), no further. The
    // light, far to the left, an orange square standing whole on the map's left edge.
    let light = dvec3(-50.0, 5.0, -5.0);
    let frame = rendered(vec![], light, Camera::default());
    let inset = (README_MARKER_RADIUS as f64 + 0.5) * README_MAP_SIDE / VIEW as f64; // 3.5 pixels
    let edge = dvec3(README_MAP_CORNER.x + inset, 0.0, light.z);
    let [pink, orange] = [ORIGIN, edge].map(|point| map_near(&frame, point, README_MARKER_RADIUS));
    let row =
        [-1.2, -0.9, 0.0, 0.9, 1.2].map(|x| drawn_near(&frame, dvec3(x, 0.0, -1.0), CAMERA_COLOR));
    assert!(
        pink.iter().all(|&pixel| pixel == CAMERA_COLOR)
            && orange.iter().all(|&pixel| pixel == LIGHT_COLOR)
            && row == [false, true, true, true, false],
        "the eye should be a pink square 7 pixels wide at (0, 0, 0) on the map, the light an orange one on its left edge around {edge}, and the screen's row a pink line from x = -1 to 1 at z = -1; they are {pink:06x?} and {orange:06x?}, and at x = -1.2, -0.9, 0, 0.9 and 1.2 the row is drawn: {row:?}: look at the end of draw_slice, `fit`, and the screen's row."
    );
}

#[test]
fn a_tilted_plane_outlines_a_ball_where_it_cuts_it() {
    // Turned and tilted up: a red ball 5 ahead and 0.4 off the plane is cut in a circle of radius
    // √(1 - 0.4²), drawn on its far side, which no ray reaches.
    let camera = camera_at(ORIGIN, 0.6, 0.3);
    let matrix = camera_matrix(camera);
    let ahead = matrix * (5.0 * AHEAD);
    let red_ball = ball(ahead + matrix * (0.4 * UP), 1.0, RED, 0.0);
    let frame = rendered(vec![red_ball], ahead + 5.0 * UP, camera);
    let circle = 1.0f64 - 0.4 * 0.4; // its radius squared
    let far_side =
        [-0.5, 0.0, 0.5].map(|x| ahead + matrix * dvec3(x, 0.0, -(circle - x * x).sqrt()));
    let drawn = far_side.map(|point| drawn_near(&frame, point, RED_ON_THE_MAP));
    assert!(
        drawn == [true; 3],
        "the red ball should be outlined in red through {far_side:?}; it is: {drawn:?}: look at draw_slice's circles."
    );
}

#[test]
fn every_10th_ray_is_drawn_from_the_screen_to_its_hit_and_a_dot_there() {
    // A level camera over the floor, and a ball of radius 0.1, 5 out on the sampled ray just
    // left of the middle: that ray is drawn in yellow from the screen, 1 out, not before, to its
    // hit, 4.9 out, and ends there in a dot 3 pixels wide. The next sampled ray, 10 columns on,
    // never comes down to the floor: it is sky blue. 6 out they are 9 pixels apart, the map black
    // between them, as draw_slice clears it each frame.
    let rays = sampled(Camera::default());
    let (ray, next) = (rays[NEAR_MIDDLE], rays[NEAR_MIDDLE + 1]);
    let frame = rendered(
        vec![checkered_floor(), ball(ray * 5.0, 0.1, RED, 0.0)],
        UP,
        Camera::default(),
    );
    let drawn = [0.6, 2.5, 5.5].map(|t| drawn_near(&frame, ray * t, RAY_COLOR));
    let dot = map_near(&frame, ray * 4.9, 1);
    let between = map_near(&frame, (ray + next).normalize() * 6.0, 0);
    assert!(
        drawn == [false, true, false]
            && dot == [RAY_COLOR; 9]
            && drawn_near(&frame, next * 6.0, MISS_COLOR)
            && between == [BACKGROUND],
        "the sampled ray along {ray} should be drawn in yellow 2.5 out, not 0.6 out (before the screen) nor 5.5 (past its hit), and end in a yellow dot 3 pixels wide 4.9 out; the next one, along {next}, in sky blue, and the map black between them 6 out. The ray is drawn {drawn:?}, the dot is {dot:06x?}, between them the map is {between:06x?}: look at SAMPLED_EVERY, draw_slice, follow and draw_ray."
    );
}

#[test]
fn a_shadow_ray_runs_to_the_light_or_to_what_blocks_it() {
    // A ball of radius 0.05, 5 out on the sampled ray just left of the middle, which alone meets
    // it, and the light 4 to the left and 2 nearer: the hit's shadow ray runs to the light (rust),
    // or, with a ball half way, up to that ball (violet) and no further.
    let ray = sampled(Camera::default())[NEAR_MIDDLE];
    let hit = ray * 4.95;
    let light = hit + dvec3(-4.0, 0.0, 2.0);
    for (other, color) in [
        (light + 2.0 * UP, SHADOW_COLOR),
        ((hit + light) / 2.0, BLOCKED_COLOR),
    ] {
        let balls = vec![ball(ray * 5.0, 0.05, RED, 0.0), ball(other, 0.5, RED, 0.0)];
        let frame = rendered(balls, light, Camera::default());
        let drawn = [0.2, 0.8].map(|share| drawn_near(&frame, hit + (light - hit) * share, color));
        assert!(
            drawn == [true, color == SHADOW_COLOR],
            "with another ball at {other}, the shadow ray from {hit} to the light at {light} should be drawn in {color:06x} a fifth of the way and, if nothing is in the way, four fifths; it is: {drawn:?}: look at draw_slice's shadow rays."
        );
    }
}

#[test]
fn a_mirror_ray_leaves_a_mirror_along_r_and_none_leaves_a_matte_surface() {
    // A wall x = 3, N = (-1, 0, 0): the last sampled ray meets it at H, and from a mirror its
    // mirror ray R = D - 2(D.N)N, D with its x turned back, crosses x = 0 as far on: at z = 2 H.z.
    let ray = *sampled(Camera::default()).last().unwrap();
    let (normal, to_wall) = (-RIGHT, 3.0 / ray.x);
    let mirrored = ray - 2.0 * ray.dot(normal) * normal;
    let crossing = (ray + mirrored) * to_wall;
    for reflectivity in [1.0, 0.0] {
        let wall = Primitive::Plane {
            normal: to_vec3(normal),
            offset: 3.0,
        };
        let frame = rendered(
            vec![object(wall, WHITE, reflectivity, false)],
            9.0 * UP,
            Camera::default(),
        );
        let drawn = drawn_near(&frame, crossing, MIRROR_COLOR);
        assert!(
            drawn == (reflectivity > 0.0),
            "a wall of reflectivity {reflectivity}: a teal mirror ray from {} crossing {crossing} is drawn: {drawn}, but a mirror ray leaves a mirror and none a matte surface: look at Hit::mirror_ray and draw_slice's mirror rays.",
            ray * to_wall
        );
    }
}
