//! Step 5: the primitives' Intersect: the plane p.N + d = 0 at t = -(O.N + d) / (D.N), the sphere
//! (p - C).(p - C) = r² at its near root, or from inside at its far one; 0 < t < ray.t.
use super::*;

/// Does a ray from `origin` along `direction`, reaching `reach`, hit the primitive at t = `expected`?
fn hits(
    (primitive, _): (Primitive, Material),
    origin: DVec3,
    direction: DVec3,
    reach: f64,
    expected: Option<f64>,
) {
    let found = primitive.intersect(&Ray::new(to_vec3(origin), to_vec3(direction), reach));
    let right = match (found, expected) {
        (Some(t), Some(expected)) => (t - expected).abs() < 1e-9,
        (found, expected) => found == expected,
    };
    assert!(
        right,
        "a ray from {origin} along {direction}, reaching {reach}, should hit at t = {expected:?}, not {found:?}: look at Primitive::intersect."
    );
}

#[test]
fn a_ray_hits_a_sphere_at_its_near_root_from_outside_and_at_its_far_root_from_inside() {
    // A ball of radius 2, 5 ahead. A ray along -z 1.5 off its centre meets it √(2² - 1.5²) =
    // √1.75 before and after the point nearest the centre; not if it reaches only 3, or is 2.5
    // off the centre, or goes away.
    let sphere = || ball(5.0 * AHEAD, 2.0, RED, 0.0);
    let far = f64::INFINITY;
    hits(
        sphere(),
        1.5 * RIGHT,
        AHEAD,
        far,
        Some(5.0 - 1.75f64.sqrt()),
    );
    hits(
        sphere(),
        dvec3(1.5, 0.0, -5.0),
        AHEAD,
        far,
        Some(1.75f64.sqrt()),
    );
    hits(sphere(), 1.5 * RIGHT, AHEAD, 3.0, None);
    hits(sphere(), 2.5 * RIGHT, AHEAD, far, None);
    hits(sphere(), ORIGIN, -AHEAD, far, None);
}

#[test]
fn a_ray_hits_a_plane_at_minus_o_dot_n_plus_d_over_d_dot_n() {
    // The floor y = -1 from (0, 2, 0), 45 degrees down: at (0, -1, -3), 3√2 away; not if the ray
    // reaches only 4. Straight up, or along the floor, the ray misses it.
    let down = dvec3(0.0, -1.0, -1.0);
    hits(
        checkered_floor(),
        2.0 * UP,
        down,
        f64::INFINITY,
        Some(3.0 * 2f64.sqrt()),
    );
    hits(checkered_floor(), 2.0 * UP, down, 4.0, None);
    hits(checkered_floor(), ORIGIN, UP, f64::INFINITY, None);
    hits(checkered_floor(), ORIGIN, RIGHT, f64::INFINITY, None);
}
