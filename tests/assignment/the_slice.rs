//! The 2D slice, the assignment's "for y = 0, visualize every 10th ray": the plane of the screen's
//! middle row seen from above, with the eye, the screen, the light, the balls where the plane cuts
//! them, and every 10th ray of that row with its hit, shadow and mirror rays.
use super::*;

/// The direction of the sampled ray nearest the middle, through column 250, from the start.
fn near_middle() -> DVec3 {
    sampled(Camera::default())[VIEW / 2 / README_SAMPLED_EVERY]
}

#[test]
fn the_eye_and_the_light_are_squares_7_pixels_wide() {
    let light = dvec3(-2.0, 5.0, -5.0);
    let frame = frame(vec![], light, Camera::default());
    for (point, color) in [(ORIGIN, CAMERA_COLOR), (light, LIGHT_COLOR)] {
        assert!(
            map_near(&frame, point, README_MARKER_RADIUS) == [color; 49],
            "the marker at {point} should be a square of {color:06x} 7 pixels wide: look at the end of draw_slice."
        );
    }
}

#[test]
fn from_off_the_map_the_eye_stands_on_its_edge_and_its_rays_cross_it() {
    // The eye 30 behind the map: its square stands whole on the map's bottom edge, and the ray
    // nearest the middle comes in over that edge and runs on to a ball ahead.
    let eye = -30.0 * AHEAD;
    let frame = frame(
        vec![ball(5.0 * AHEAD, 3.0, RED, 0.0)],
        9.0 * UP,
        camera(eye, 0.0, 0.0),
    );
    let edge = dvec3(
        0.0,
        0.0,
        MAP_CORNER.z + (VIEW - 1 - README_MARKER_RADIUS) as f64 / MAP_SCALE,
    );
    let on_map = eye + near_middle() * 28.0 / -near_middle().z; // at z = 2
    assert!(
        map_near(&frame, edge, README_MARKER_RADIUS) == [CAMERA_COLOR; 49]
            && drawn_near(&frame, on_map, RAY_COLOR),
        "from 30 behind the map, the eye's square should stand on its bottom edge around {edge}, and the sampled ray nearest the middle cross it at {on_map}: look at `fit` in draw_slice and at draw_ray."
    );
}

#[test]
fn the_screens_middle_row_is_a_line_from_c_minus_right_to_c_plus_right() {
    // From the start, C - right = (-1, 0, -1) and C + right = (1, 0, -1): the map is pink at each
    // pixel between them, and not past them.
    let frame = frame(vec![], ORIGIN, Camera::default());
    let pink = |x: f64| map_near(&frame, dvec3(x, 0.0, -1.0), 0) == [CAMERA_COLOR];
    let row: Vec<bool> = (-40..40)
        .map(|i| pink((f64::from(i) + 0.5) / 40.0))
        .collect();
    assert!(
        !row.contains(&false) && !pink(-1.1) && !pink(1.1),
        "the screen's middle row should be drawn from (-1, -1) to (1, -1) on the map, pixel after pixel ({row:?}), and no further: look at draw_slice's row and draw_ray."
    );
}

#[test]
fn a_tilted_plane_outlines_the_balls_it_cuts_and_no_other() {
    // Tilted up: a red ball 5 ahead and 0.4 off the plane is cut in a circle of radius
    // √(1 - 0.4²), drawn on its far side, which no ray reaches; a green ball 1.2 off it is not cut.
    let camera = camera(dvec3(0.5, 0.3, 1.0), 0.6, 0.3);
    let turn = turn(camera);
    let ahead = to_dvec3(camera.position) + turn * (5.0 * AHEAD);
    let balls = vec![
        ball(ahead + turn * (0.4 * UP), 1.0, RED, 0.0),
        ball(ahead + turn * dvec3(-2.5, 1.2, 0.0), 0.8, UP, 0.0),
    ];
    let frame = frame(balls, ahead + 5.0 * UP, camera);
    let far_side =
        [-0.5, 0.0, 0.5].map(|x| ahead + turn * dvec3(x, 0.0, -(0.84f64 - x * x).sqrt()));
    assert!(
        far_side
            .iter()
            .all(|&point| drawn_near(&frame, point, 0xff0000))
            && !frame.contains(&0x00ff00),
        "the red ball should be outlined in red through {far_side:?}, the green ball not at all: look at draw_slice's circles."
    );
}

#[test]
fn a_sampled_ray_runs_from_the_screen_to_its_hit_and_ends_in_a_dot() {
    // A matte ball of radius 1 dead ahead on the sampled ray nearest the middle, 5 out: the ray is
    // drawn up to its hit, 4 out, ends there in a dot 3 pixels wide, and nothing goes on from it.
    let d = near_middle();
    let frame = frame(
        vec![ball(d * 5.0, 1.0, RED, 0.0)],
        9.0 * UP,
        Camera::default(),
    );
    let drawn = [2.5, 4.5].map(|t| drawn_near(&frame, d * t, RAY_COLOR));
    assert!(
        map_near(&frame, d * 4.0, 1) == [RAY_COLOR; 9]
            && drawn == [true, false]
            && !frame.contains(&MIRROR_COLOR),
        "the sampled ray nearest the middle should be drawn up to the matte ball it meets 4 out, along {d}, end there in a dot 3 pixels wide, and nothing go on: look at follow and draw_ray."
    );
}

#[test]
fn every_10th_ray_is_drawn_from_the_screen_on_and_nothing_between() {
    // A level camera over the floor: its sampled rays never come down to it, so are all sky blue.
    // 6 out, they are 5 to 9 pixels apart; between them the map is black, as draw_slice clears it
    // each frame. The first, along about (-1, 0, -1), starts at the screen, √2 out.
    let frame = frame(vec![floor()], UP, Camera::default());
    let rays = sampled(Camera::default());
    for pair in rays[rays.len() / 4..rays.len() * 3 / 4].windows(2) {
        let [ray, between] = [pair[0], pair[0] + pair[1]].map(|d| d.normalize() * 6.0);
        assert!(
            drawn_near(&frame, ray, MISS_COLOR) && map_near(&frame, between, 0) == [BACKGROUND],
            "the map should show every 10th ray of the middle row in sky blue, {ray} among them, and be black between them, at {between}: look at SAMPLED_EVERY and draw_slice."
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
    // A ball 6 out on the sampled ray nearest the middle, the light 6 to the left of the hit: the
    // shadow ray runs to the light (rust), or, with a ball halfway, to that ball (violet).
    let hit = near_middle() * 5.0;
    for (blocker, color) in [(0.0, SHADOW_COLOR), (0.5, BLOCKED_COLOR)] {
        let balls = vec![
            ball(near_middle() * 6.0, 1.0, RED, 0.0),
            ball(hit - 3.0 * RIGHT, blocker, RED, 0.0),
        ];
        let frame = frame(balls, hit - 6.0 * RIGHT, Camera::default());
        let drawn = [1.0, 5.0].map(|x| drawn_near(&frame, hit - x * RIGHT, color));
        assert!(
            drawn == [true, blocker == 0.0],
            "the shadow ray from {hit} should be drawn in {color:06x} to the light, 6 to the left, or to a ball of radius {blocker} halfway: look at draw_slice's shadow rays."
        );
    }
}

#[test]
fn a_mirror_ray_leaves_a_mirror_along_r() {
    // A mirror ball 5 out, its centre 0.25 right of the sampled ray nearest the middle: the ray
    // meets it on its left, and R = D - 2(D.N)N sends it back across z = 0.3, behind the eye,
    // where nothing else is drawn.
    let d = near_middle();
    let center = d * 5.0 + 0.25 * RIGHT;
    let frame = frame(
        vec![ball(center, 1.0, WHITE, 0.9)],
        center + 9.0 * UP,
        Camera::default(),
    );
    let hit = d * (center.dot(d) - (1.0 - center.reject_from(d).length_squared()).sqrt());
    let r = d - (hit - center) * 2.0 * d.dot(hit - center);
    let behind = hit + r * ((0.3 - hit.z) / r.z);
    assert!(
        drawn_near(&frame, behind, MIRROR_COLOR),
        "the mirror ray from {hit} should cross {behind}: look at Hit::mirror_ray and draw_slice's mirror rays."
    );
}

#[test]
fn the_sampled_rays_are_drawn_over_the_shadow_and_mirror_rays() {
    // A mirror ball dead ahead on the sampled ray nearest the middle, the light behind the eye on
    // it: that ray's mirror and shadow rays go straight back along it. It shows on top.
    let d = near_middle();
    let frame = frame(
        vec![ball(d * 5.0, 1.0, WHITE, 0.9)],
        d * -2.0,
        Camera::default(),
    );
    assert!(
        map_near(&frame, d * 2.5, 0) == [RAY_COLOR],
        "the sampled ray nearest the middle should show on top of the mirror and shadow rays that go back along it: look at the order in which draw_slice draws."
    );
}
