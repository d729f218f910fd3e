//! The 2D slice, the assignment's "for y = 0, visualize every 10th ray": the plane of the screen's
//! middle row seen from above, with the eye, the screen, the light, the balls where the plane cuts
//! them, and every 10th ray of that row with its hit, shadow and mirror rays.
use super::*;

/// The direction of the sampled ray nearest the screen's middle, for the camera given.
fn near_middle(camera: Camera) -> DVec3 {
    sampled(camera)[VIEW / 2 / README_SAMPLED_EVERY]
}

/// A map marker's square, MARKER_RADIUS pixels either side of its middle: 7 x 7 = 49 pixels.
const MARKER_PIXELS: usize = (2 * README_MARKER_RADIUS + 1) * (2 * README_MARKER_RADIUS + 1);

#[test]
fn the_eye_and_the_light_are_squares_7_pixels_wide() {
    let light = dvec3(-2.0, 5.0, -5.0);
    let frame = rendered(vec![], light, Camera::default());
    for (point, color, name) in [
        (ORIGIN, CAMERA_COLOR, "pink"),
        (light, LIGHT_COLOR, "orange"),
    ] {
        let square = map_near(&frame, point, README_MARKER_RADIUS);
        let around = map_near(&frame, point, README_MARKER_RADIUS + 1);
        let count = around.iter().filter(|&&pixel| pixel == color).count();
        assert!(
            square == [color; MARKER_PIXELS] && count == MARKER_PIXELS,
            "the {name} marker at {point} should be a square 7 pixels wide, all {name} and no more; {count} pixels around it are: look at the end of draw_slice."
        );
    }
}

#[test]
fn from_off_the_map_the_eye_stands_on_its_edge_and_its_rays_cross_it() {
    // The eye 30 behind the map: its square stands whole on the map's bottom edge, and the ray
    // nearest the middle comes in over that edge and runs on to a ball ahead, crossing z = 2.
    let eye = -30.0 * AHEAD;
    let frame = rendered(
        vec![ball(5.0 * AHEAD, 3.0, RED, 0.0)],
        9.0 * UP,
        camera_at(eye, 0.0, 0.0),
    );
    let marker = (VIEW - 1 - README_MARKER_RADIUS) as f64 * README_MAP_SIDE / VIEW as f64;
    let edge = dvec3(0.0, 0.0, README_MAP_CORNER.z + marker); // its middle, 3 pixels up
    let ray = near_middle(Camera::default());
    let on_map = eye + ray * (28.0 / -ray.z); // 28 ahead, at z = 2
    assert!(
        map_near(&frame, edge, README_MARKER_RADIUS) == [CAMERA_COLOR; MARKER_PIXELS]
            && drawn_near(&frame, on_map, RAY_COLOR),
        "from 30 behind the map, the eye's pink square should stand on its bottom edge around {edge}, and the yellow ray nearest the middle cross it at {on_map}: look at `fit` in draw_slice and at draw_ray."
    );
}

#[test]
fn the_screens_middle_row_is_a_line_from_c_minus_right_to_c_plus_right() {
    // From the start, C - right = (-1, 0, -1) and C + right = (1, 0, -1): the map is pink at each
    // pixel between them, and not past them.
    let frame = rendered(vec![], ORIGIN, Camera::default());
    let pink = |x: f64| map_near(&frame, dvec3(x, 0.0, -1.0), 0) == [CAMERA_COLOR];
    let pixel = README_MAP_SIDE / VIEW as f64; // a map pixel's width, in world units
    let missing = (1..(2.0 / pixel) as usize)
        .map(|i| -1.0 + i as f64 * pixel)
        .find(|&x| !pink(x));
    assert!(
        missing.is_none() && !pink(-1.1) && !pink(1.1),
        "the screen's middle row should be drawn in pink from (-1, -1) to (1, -1) on the map, pixel after pixel, and no further; it is missing at x = {missing:?}, or goes on past -1.1 or 1.1: look at draw_slice's row and draw_ray."
    );
}

#[test]
fn a_tilted_plane_outlines_the_balls_it_cuts_and_no_other() {
    // Tilted up: a red ball 5 ahead and 0.4 off the plane is cut in a circle of radius
    // √(1 - 0.4²), drawn on its far side, which no ray reaches; a green ball 1.2 off it is not cut.
    let camera = camera_at(dvec3(0.5, 0.3, 1.0), 0.6, 0.3);
    let matrix = camera_matrix(camera);
    let ahead = to_dvec3(camera.position) + matrix * (5.0 * AHEAD);
    let green = dvec3(0.0, 1.0, 0.0);
    let balls = vec![
        ball(ahead + matrix * (0.4 * UP), 1.0, RED, 0.0),
        ball(ahead + matrix * dvec3(-2.5, 1.2, 0.0), 0.8, green, 0.0),
    ];
    let frame = rendered(balls, ahead + 5.0 * UP, camera);
    let circle = 1.0f64 - 0.4 * 0.4; // its radius squared
    let far_side =
        [-0.5, 0.0, 0.5].map(|x| ahead + matrix * dvec3(x, 0.0, -(circle - x * x).sqrt()));
    assert!(
        far_side
            .iter()
            .all(|&point| drawn_near(&frame, point, RED_ON_THE_MAP))
            && !on_the_map(&frame, 0x00ff00),
        "the red ball should be outlined in red through {far_side:?}, the green ball not at all: look at draw_slice's circles."
    );
}

#[test]
fn a_sampled_ray_runs_from_the_screen_to_its_hit_and_ends_in_a_dot() {
    // A camera moved, turned and tilted down, and a matte ball of radius 1, 5 out on its sampled
    // ray nearest the middle: the ray is drawn up to its hit, 4 out, ends there in a dot 3 pixels
    // wide, and nothing goes on from it.
    let camera = camera_at(dvec3(0.5, 0.3, 1.0), 0.6, -0.3);
    let (eye, ray) = (to_dvec3(camera.position), near_middle(camera));
    let frame = rendered(vec![ball(eye + ray * 5.0, 1.0, RED, 0.0)], 9.0 * UP, camera);
    let dot = map_near(&frame, eye + ray * 4.0, 1);
    let around = map_near(&frame, eye + ray * 4.0, 2)
        .iter()
        .filter(|&&pixel| pixel == RAY_COLOR)
        .count();
    let drawn = [2.5, 4.5].map(|t| drawn_near(&frame, eye + ray * t, RAY_COLOR));
    assert!(
        dot == [RAY_COLOR; 9]
            && around < 16
            && drawn == [true, false]
            && !on_the_map(&frame, MIRROR_COLOR),
        "the sampled ray should be drawn in yellow up to the matte ball it meets 4 out, along {ray}, end there in a dot 3 pixels wide, and nothing go on from it; 2.5 and 4.5 out it is drawn: {drawn:?}, the dot is {dot:06x?}, with {around} of the 25 pixels around its middle yellow, where the ray in and a dot 3 wide make under 16: look at follow and draw_ray."
    );
}

#[test]
fn every_10th_ray_is_drawn_from_the_screen_on_and_nothing_between() {
    // A level camera over the floor: its sampled rays never come down to it, so are all sky blue.
    // 6 out, neighbouring ones are several pixels apart; between them the map is black, as
    // draw_slice clears it each frame. The first, along about (-1, 0, -1), starts at the screen,
    // √2 out.
    let frame = rendered(vec![checkered_floor()], UP, Camera::default());
    let rays = sampled(Camera::default());
    for pair in rays[rays.len() / 4..rays.len() * 3 / 4].windows(2) {
        let ray = pair[0] * 6.0;
        let between = (pair[0] + pair[1]).normalize() * 6.0;
        let seen = map_near(&frame, between, 0)[0];
        assert!(
            drawn_near(&frame, ray, MISS_COLOR) && seen == BACKGROUND,
            "the map should show every 10th ray of the middle row in sky blue, {ray} among them, and be black between them, not {seen:06x} at {between}: look at SAMPLED_EVERY and draw_slice."
        );
    }
    assert!(
        !drawn_near(&frame, rays[0] * 0.6, MISS_COLOR)
            && drawn_near(&frame, rays[0] * 2.0, MISS_COLOR),
        "the first sampled ray should be drawn from the screen on, √2 out, not before: look at where draw_slice starts the sampled rays."
    );
}

#[test]
fn a_shadow_ray_runs_to_the_light_or_to_what_blocks_it() {
    // A ball of radius 0.05, 5 out on the sampled ray nearest the middle, which alone meets it,
    // and the light 4 to the left and 2 nearer: the hit's shadow ray runs to the light (rust), or,
    // with a ball halfway, up to that ball (violet) and no further.
    let ray = near_middle(Camera::default());
    let hit = ray * 4.95;
    let light = hit + dvec3(-4.0, 0.0, 2.0);
    for (blocker, color) in [(false, SHADOW_COLOR), (true, BLOCKED_COLOR)] {
        let mut balls = vec![ball(ray * 5.0, 0.05, RED, 0.0)];
        if blocker {
            balls.push(ball((hit + light) / 2.0, 0.5, RED, 0.0));
        }
        let frame = rendered(balls, light, Camera::default());
        let drawn = [0.2, 0.8].map(|share| drawn_near(&frame, hit + (light - hit) * share, color));
        assert!(
            drawn == [true, !blocker],
            "with a ball in the way: {blocker}, the shadow ray from {hit} to the light at {light} should be drawn in {color:06x} a fifth of the way and, if nothing is in the way, four fifths; it is: {drawn:?}: look at draw_slice's shadow rays."
        );
    }
}

#[test]
fn a_mirror_ray_leaves_a_mirror_along_r() {
    // A mirror ball of radius 0.05, 5 out, its centre 0.01 right of the sampled ray nearest the
    // middle, which alone meets it, on its left: R = D - 2(D.N)N sends that ray back across
    // z = 0.3, behind the eye, where nothing else is drawn.
    let ray = near_middle(Camera::default());
    let center = ray * 5.0 + 0.01 * RIGHT;
    let frame = rendered(
        vec![ball(center, 0.05, WHITE, 0.9)],
        center + 9.0 * UP,
        Camera::default(),
    );
    let miss = center.reject_from(ray).length(); // how far the ray passes from the centre
    let hit = ray * (center.dot(ray) - (0.05f64 * 0.05 - miss * miss).sqrt());
    let normal = (hit - center) / 0.05;
    let mirrored = ray - normal * 2.0 * ray.dot(normal);
    let behind = hit + mirrored * ((0.3 - hit.z) / mirrored.z);
    assert!(
        drawn_near(&frame, behind, MIRROR_COLOR),
        "the teal mirror ray from {hit} should cross {behind}: look at Hit::mirror_ray and draw_slice's mirror rays."
    );
}

#[test]
fn the_sampled_rays_are_drawn_over_the_shadow_and_mirror_rays() {
    // A mirror ball dead ahead on the sampled ray nearest the middle, the light behind the eye on
    // it: that ray's mirror and shadow rays go straight back along it. It shows on top.
    let ray = near_middle(Camera::default());
    let frame = rendered(
        vec![ball(ray * 5.0, 1.0, WHITE, 0.9)],
        ray * -2.0,
        Camera::default(),
    );
    let seen = map_near(&frame, ray * 2.5, 0)[0];
    assert!(
        seen == RAY_COLOR,
        "the yellow sampled ray should show on top of the mirror and shadow rays that go back along it, not {seen:06x}: look at the order in which draw_slice draws."
    );
}
