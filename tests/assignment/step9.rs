//! Step 9: shadow rays and reflections: a surface's colour × (ambient + (1 - ambient) N.L where
//! its shadow ray reaches the light), mixed by reflectivity with what R = D - 2(D.N)N sees.
use super::*;

/// The share of the light a surface gets: ambient + (1 - ambient) N.L.
fn lit(n_dot_l: f64) -> f64 {
    README_AMBIENT + (1.0 - README_AMBIENT) * n_dot_l
}

#[test]
fn a_surface_is_lit_ambient_plus_1_minus_ambient_times_n_dot_l() {
    // Straight ahead, P = (0, 0, -3) on a red ball of radius 20, N = (0, 0, 1) towards the eye: lit
    // from 60 degrees to the side (N.L = 1/2), then from behind the ball (the ambient share
    // alone); then P seen from inside a ball, N turned to face the ray, lit from the side again.
    let beside = dvec3(5.0 * 3f64.sqrt(), 0.0, 2.0); // P + 10 (sin 60°, 0, cos 60°)
    for (center, light, n_dot_l) in [
        (23.0 * AHEAD, beside, 0.5),
        (23.0 * AHEAD, 50.0 * AHEAD, 0.0),
        (-17.0 * AHEAD, beside, 0.5),
    ] {
        let seen = traced(vec![ball(center, 20.0, RED, 0.0)], light, ORIGIN, AHEAD);
        let expected = RED * lit(n_dot_l);
        assert!(
            seen.abs_diff_eq(expected, 1e-3),
            "where N.L = {n_dot_l}, the red ball centred at {center} should show {expected}, not {seen}: look at Scene::trace, nearest_hit's N, turned to face the ray, and, from inside, Primitive::intersect's far root."
        );
    }
}

#[test]
fn only_a_ball_between_a_point_and_the_light_shadows_it() {
    // The light 2 over a ball over the floor: the floor at P = (0.1, -1, -4.9) has the ball
    // between it and the light, so shows the ambient light alone. With the ball beyond the light,
    // it is lit. Seen from (0, 0.5, 0), rounding puts P a hair under the floor: from P itself, its
    // shadow ray would meet the floor at once (acne).
    let (light, point) = (dvec3(0.0, 2.0, -5.0), dvec3(0.1, -1.0, -4.9));
    let [between, beyond] = [5.0 * AHEAD, light + UP].map(|center| {
        let objects = vec![
            object(floor_plane(), WHITE, 0.0, false),
            ball(center, 0.5, RED, 0.0),
        ];
        traced(objects, light, 0.5 * UP, point).y // white: its green is the share of the light
    });
    let share = lit((light - point).normalize().y);
    assert!(
        (between - README_AMBIENT).abs() < 1e-3 && (beyond - share).abs() < 1e-3,
        "the white floor's green should be {README_AMBIENT} in the shadow of a ball between it and the light, and {share} with the ball beyond the light, not {between} and {beyond}: look at Scene::shadow_ray, trace and Hit::outgoing."
    );
}

#[test]
fn a_mirror_shows_what_its_mirror_ray_meets() {
    // A mirror floor and a red ball over it: by R = D - 2(D.N)N, the floor shows the ball where
    // its mirror image, as far under the floor y = -1 as the ball is over it, would be.
    let center = dvec3(1.0, 0.5, -6.0);
    let objects = vec![
        object(floor_plane(), WHITE, 1.0, false),
        ball(center, 0.5, RED, 0.0),
    ];
    let image = center - 2.0 * (center.y + 1.0) * UP; // center.y + 1 over the floor
    let seen = traced(objects, 3.0 * AHEAD, ORIGIN, image);
    assert!(
        is_red(seen),
        "the mirror floor should show the red ball's image at {image}, not {seen}: look at Hit::mirror_ray."
    );
}

#[test]
fn a_ray_between_facing_half_mirrors_mixes_in_5_bounces() {
    // A red floor and a blue ceiling, y = -1 and y = 1, half mirrors, and the light between them
    // (N.L = 1). A ray straight down bounces between them: its hit k (0 the first, then one a
    // bounce) brings back half of that mirror's colour × 1/2^k, the last hit all of it.
    let ceiling = Primitive::Plane {
        normal: vec3(0.0, -1.0, 0.0),
        offset: 1.0,
    };
    let blue = dvec3(0.0, 0.0, 1.0);
    let objects = vec![
        object(floor_plane(), RED, 0.5, false),
        object(ceiling, blue, 0.5, false),
    ];
    let mut expected = ORIGIN;
    for k in 0..=README_MAX_DEPTH {
        let color = if k % 2 == 0 { RED } else { blue };
        let own = if k == README_MAX_DEPTH { 1.0 } else { 0.5 };
        expected += color * own / 2f64.powi(k as i32);
    }
    let seen = traced(objects, ORIGIN, ORIGIN, -UP);
    assert!(
        seen.abs_diff_eq(expected, 1e-3),
        "after {README_MAX_DEPTH} bounces the ray should bring back {expected}, not {seen}: look at MAX_DEPTH, the end of Scene::trace and Hit::mirror_ray."
    );
}
