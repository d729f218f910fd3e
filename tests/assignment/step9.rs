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
    for (light, n_dot_l) in [
        (dvec3(5.0 * 3f64.sqrt(), 0.0, 2.0), 0.5),
        (50.0 * AHEAD, 0.0),
    ] {
        let frame = frame(
            vec![ball(23.0 * AHEAD, 20.0, RED, 0.0)],
            light,
            Camera::default(),
        );
        let (red, expected) = (rgb(&frame, MIDDLE)[0], bytes(RED * lit(n_dot_l))[0]);
        assert!(
            red.abs_diff(expected) <= 1,
            "where N.L = {n_dot_l}, the red ball should show red {expected}, not {red}: look at Scene::trace and nearest_hit's N."
        );
    }
}

#[test]
fn only_a_ball_between_a_point_and_the_light_shadows_it() {
    // The light 2 over a ball over the floor: the floor at (0.2, -1, -4.8) sees the light through
    // the ball, so shows the ambient light alone, on an odd square (0 + -5 is odd). With the ball
    // beyond the light, it shows what it shows with the ball far off.
    let (light, camera) = (dvec3(0.0, 2.0, -5.0), camera(UP, 0.0, -0.3));
    let pixel = pixel_of(camera, dvec3(0.2, -1.0, -4.8));
    let [between, beyond, far] = [5.0 * AHEAD, light + UP, 1e9 * UP].map(|center| {
        rgb(
            &frame(vec![floor(), ball(center, 0.5, RED, 0.0)], light, camera),
            pixel,
        )
    });
    let shadow = bytes(WHITE * README_AMBIENT * README_ODD_SQUARE_BRIGHTNESS);
    assert!(
        between == shadow && beyond == far,
        "the floor should show RGB {shadow:?} in the shadow of a ball between it and the light, and with the ball beyond the light what it shows without, {far:?}; not {between:?} and {beyond:?}: look at Scene::shadow_ray and trace."
    );
}

#[test]
fn a_ray_leaving_a_surface_does_not_meet_it_again() {
    // Floor points 10 to 10^6 out, each lit from high straight above: all the light. Its shadow
    // ray from the floor, or from just under it by rounding, would meet the floor at once.
    for i in 0..30 {
        let (distance, angle) = (10f64.powi(i % 6 + 1), f64::from(i));
        let point = dvec3(distance * angle.cos(), -1.0, distance * angle.sin());
        let scene = scene(
            vec![object(floor_plane(), WHITE, 0.0, false)],
            point + distance * UP,
        );
        let seen = to_dvec3(scene.trace(
            Ray::new(vec3(0.0, 0.0, 0.0), to_vec3(point), f64::INFINITY),
            0,
        ));
        assert!(
            seen.abs_diff_eq(WHITE, 1e-3),
            "the floor {distance} out, lit from high above, should be white, not {seen}: its shadow ray meets the floor it leaves. Look at Hit::outgoing."
        );
    }
}

#[test]
fn a_mirror_shows_what_its_mirror_ray_meets() {
    // A mirror floor and a red ball over it: by R = D - 2(D.N)N, the floor shows the ball where
    // its mirror image under the floor would be.
    let center = dvec3(1.0, 0.5, -6.0);
    let objects = vec![
        object(floor_plane(), WHITE, 1.0, false),
        ball(center, 0.5, RED, 0.0),
    ];
    let image = center * dvec3(1.0, -1.0, 1.0) - 2.0 * UP; // mirrored in y = -1
    let seen = rgb(
        &frame(objects, 3.0 * AHEAD, Camera::default()),
        pixel_of(Camera::default(), image),
    );
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
        let own = if k == README_MAX_DEPTH { 1.0 } else { 0.5 };
        expected += [RED, blue][k as usize % 2] * lit(0.1f64.sqrt()) * own / 2f64.powi(k as i32);
    }
    let down = Ray::new(vec3(0.0, 0.0, 0.0), vec3(0.0, -1.0, 0.0), f64::INFINITY);
    let seen = to_dvec3(scene(objects, 3.0 * AHEAD).trace(down, 0));
    assert!(
        seen.abs_diff_eq(expected, 1e-3),
        "after {README_MAX_DEPTH} bounces the ray should bring back {expected}, not {seen}: look at MAX_DEPTH, the end of Scene::trace and Hit::mirror_ray."
    );
}

#[test]
fn a_surface_seen_from_its_far_side_is_lit_on_that_side() {
    // From inside a ball, and from under the floor, the light outside and above: the side seen
    // faces away from it, so gets only the ambient light.
    let inside = (ball(ORIGIN, 2.0, WHITE, 0.0), Camera::default());
    let below = (
        object(floor_plane(), WHITE, 0.0, false),
        camera(-3.0 * UP, 0.0, 1.0),
    );
    for (object, camera) in [inside, below] {
        let seen = rgb(&frame(vec![object], dvec3(0.0, 5.0, -1.0), camera), MIDDLE);
        assert!(
            seen == bytes(WHITE * README_AMBIENT),
            "a surface seen from inside or below should show the ambient share of white, not RGB {seen:?}: look at nearest_hit's N, turned to face the ray, and the sphere's far root."
        );
    }
}
