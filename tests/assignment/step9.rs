//! Step 9: shadow rays and reflections: a surface's colour × (ambient + (1 - ambient) N.L where
//! its shadow ray reaches the light), mixed by reflectivity with what R = D - 2(D.N)N sees.
use super::*;

/// The share of the light a surface gets: ambient + (1 - ambient) N.L.
fn lit(n_dot_l: f64) -> f64 {
    README_AMBIENT + (1.0 - README_AMBIENT) * n_dot_l
}

#[test]
fn a_surface_is_lit_ambient_plus_1_minus_ambient_times_n_dot_l() {
    // The middle pixel sees a red ball of radius 20 at P = (0, 0, -3), N = (0, 0, 1), lit from 60
    // degrees to the side (N.L = 1/2), then from behind (the ambient share alone).
    let beside = dvec3(5.0 * 3f64.sqrt(), 0.0, 2.0); // P + 10 (sin 60°, 0, cos 60°)
    for (light, n_dot_l) in [(beside, 0.5), (50.0 * AHEAD, 0.0)] {
        let frame = rendered(
            vec![ball(23.0 * AHEAD, 20.0, RED, 0.0)],
            light,
            Camera::default(),
        );
        let red = rgb(&frame, MIDDLE)[0];
        let expected = bytes(RED * lit(n_dot_l))[0];
        assert!(
            red.abs_diff(expected) <= 1,
            "where N.L = {n_dot_l}, the red ball should show red {expected}, not {red}: look at Scene::trace and nearest_hit's N."
        );
    }
}

#[test]
fn only_a_ball_between_a_point_and_the_light_shadows_it() {
    // The light 2 over a ball over the floor: the floor at (0.2, -1, -4.8), on an odd square
    // (0 + -5 is odd), sees the light through the ball, so shows the ambient light alone. With
    // the ball beyond the light, it is lit: N.L = 3 / |(-0.2, 3, -0.2)|.
    let light = dvec3(0.0, 2.0, -5.0);
    let camera = camera_at(UP, 0.0, -0.3);
    let point = dvec3(0.2, -1.0, -4.8);
    let [between, beyond] = [5.0 * AHEAD, light + UP].map(|center| {
        let objects = vec![checkered_floor(), ball(center, 0.5, RED, 0.0)];
        rgb(&rendered(objects, light, camera), pixel_of(camera, point))[1]
    });
    let n_dot_l = (light - point).normalize().y;
    let [shadow, lit] = [README_AMBIENT, lit(n_dot_l)]
        .map(|share| bytes(WHITE * share * README_ODD_SQUARE_BRIGHTNESS)[1]);
    assert!(
        between == shadow && beyond.abs_diff(lit) <= 1,
        "the floor should show green {shadow} in the shadow of a ball between it and the light, and {lit} with the ball beyond the light, not {between} and {beyond}: look at Scene::shadow_ray and trace."
    );
}

#[test]
fn a_ray_leaving_a_surface_does_not_meet_it_again() {
    // Floor points 10 to 10^6 out, at 5 bearings each, lit from high straight above: all the
    // light. Its shadow ray from the floor, or from just under it by rounding, would meet the
    // floor at once.
    let floor = || object(floor_plane(), WHITE, 0.0, false);
    for distance in [10.0, 1e2, 1e3, 1e4, 1e5, 1e6] {
        for bearing in [0.3f64, 1.7, 2.9, 4.2, 5.5] {
            let point = dvec3(distance * bearing.cos(), -1.0, distance * bearing.sin());
            let ray = Ray::new(vec3(0.0, 0.0, 0.0), to_vec3(point), f64::INFINITY);
            let seen = to_dvec3(scene(vec![floor()], point + distance * UP).trace(ray, 0));
            assert!(
                seen.abs_diff_eq(WHITE, 1e-3),
                "the floor {distance} out, lit from high above, should be white, not {seen}: its shadow ray meets the floor it leaves. Look at Hit::outgoing."
            );
        }
    }
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
    let image = dvec3(center.x, -2.0 - center.y, center.z);
    let frame = rendered(objects, 3.0 * AHEAD, Camera::default());
    let seen = rgb(&frame, pixel_of(Camera::default(), image));
    assert!(
        is_red(seen),
        "the mirror floor should show the red ball's image at {image}, not RGB {seen:?}: look at Hit::mirror_ray."
    );
}

#[test]
fn a_ray_between_facing_half_mirrors_mixes_in_5_bounces() {
    // A red floor and a blue ceiling, y = -1 and y = 1, half mirrors, each lit alike from the side
    // (N.L = 1/√10). A ray straight down bounces between them: bounce k brings back half of its
    // mirror's lit colour × 1/2^k, the last bounce all of it.
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
        expected += color * lit(1.0 / 10f64.sqrt()) * own / 2f64.powi(k as i32);
    }
    let down = Ray::new(vec3(0.0, 0.0, 0.0), vec3(0.0, -1.0, 0.0), f64::INFINITY);
    let seen = to_dvec3(scene(objects, 3.0 * AHEAD).trace(down, 0));
    assert!(
        seen.abs_diff_eq(expected, 1e-3),
        "after {README_MAX_DEPTH} bounces the ray should bring back {expected}, not {seen}: look at MAX_DEPTH, the end of Scene::trace and Hit::mirror_ray."
    );
}

#[test]
fn the_floor_seen_from_below_gets_only_the_ambient_light() {
    // From under the floor, the light above it: the underside faces away from the light.
    let floor = object(floor_plane(), WHITE, 0.0, false);
    let seen = rgb(
        &rendered(
            vec![floor],
            dvec3(0.0, 5.0, -1.0),
            camera_at(-3.0 * UP, 0.0, 1.0),
        ),
        MIDDLE,
    );
    assert!(
        seen == bytes(WHITE * README_AMBIENT),
        "the floor's underside should show the ambient share of white, not RGB {seen:?}: look at nearest_hit's N, turned to face the ray."
    );
}
