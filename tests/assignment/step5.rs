//! Step 5: the primitives' Intersect: the plane p.N + d = 0 at t = -(O.N + d) / (D.N), the sphere
//! (p - C).(p - C) = r² at its near root, or from inside at its far one; 0 < t < ray.t.
use super::*;

/// Does a ray from `origin` along `direction`, reaching `reach`, hit `object` at t = `expected`?
fn hits(
    object: (Primitive, Material),
    origin: DVec3,
    direction: DVec3,
    reach: f64,
    expected: Option<f64>,
) {
    let found = object
        .0
        .intersect(&Ray::new(to_vec3(origin), to_vec3(direction), reach));
    assert!(
        found
            .zip(expected)
            .map_or(found == expected, |(t, expected)| (t - expected).abs()
                < 1e-9),
        "a ray from {origin} along {direction}, reaching {reach}, should hit at t = {expected:?}, not {found:?}: look at Primitive::intersect."
    );
}

#[test]
fn a_ray_hits_a_sphere_at_its_near_root_from_outside_and_at_its_far_root_from_inside() {
    // A ball of radius 2, 5 ahead. A ray along -z 1.5 off its centre meets it √(2² - 1.5²) =
    // √1.75 before and after the point nearest the centre; one 2.5 off it, or going away, misses.
    let ball = || ball(5.0 * AHEAD, 2.0, RED, 0.0);
    let far = f64::INFINITY;
    hits(ball(), 1.5 * RIGHT, AHEAD, far, Some(5.0 - 1.75f64.sqrt()));
    hits(
        ball(),
        dvec3(1.5, 0.0, -5.0),
        AHEAD,
        far,
        Some(1.75f64.sqrt()),
    );
    hits(ball(), 2.5 * RIGHT, AHEAD, far, None);
    hits(ball(), ORIGIN, -AHEAD, far, None);
}

#[test]
fn a_ray_hits_a_plane_at_minus_o_dot_n_plus_d_over_d_dot_n_before_its_reach() {
    // The floor y = -1 from the origin, 45 degrees down: at (0, -1, -1), √2 away. Straight up, or
    // along it, the ray misses it.
    let down = dvec3(0.0, -1.0, -1.0);
    hits(floor(), ORIGIN, down, f64::INFINITY, Some(2f64.sqrt()));
    hits(floor(), ORIGIN, down, 1.0, None);
    hits(floor(), ORIGIN, UP, f64::INFINITY, None);
    hits(floor(), ORIGIN, RIGHT, f64::INFINITY, None);
}
