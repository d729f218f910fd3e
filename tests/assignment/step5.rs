//! Step 5: the primitives' Intersect: the plane p.N + d = 0 at t = -(O.N + d) / (D.N), the sphere
//! (p - C).(p - C) = r² at its near root, or from inside at its far one; 0 < t < ray.t.
use super::*;

/// The t at which a ray from `origin` along `direction`, reaching `reach`, first hits `primitive`,
/// to 9 decimals; None if it misses.
fn hit(primitive: &Primitive, origin: DVec3, direction: DVec3, reach: f64) -> Option<f64> {
    let ray = Ray::new(to_vec3(origin), to_vec3(direction), reach);
    primitive.intersect(&ray).map(|t| (t * 1e9).round() / 1e9)
}

#[test]
fn a_ray_hits_a_sphere_at_its_near_root_from_outside_and_at_its_far_root_from_inside() {
    // A ball of radius 5, 10 ahead. A ray along -z 3 off its centre meets it √(5² - 3²) = 4 before
    // and after the point nearest the centre: 6 out, or 4 out from that point; not if it reaches
    // only 5.
    let (sphere, _) = ball(10.0 * AHEAD, 5.0, RED, 0.0);
    let found = [
        hit(&sphere, 3.0 * RIGHT, AHEAD, f64::INFINITY),
        hit(&sphere, dvec3(3.0, 0.0, -10.0), AHEAD, f64::INFINITY),
        hit(&sphere, 3.0 * RIGHT, AHEAD, 5.0),
    ];
    assert!(
        found == [Some(6.0), Some(4.0), None],
        "these rays should hit the ball at t = 6, at t = 4 from inside, and miss it with a reach of 5, not at {found:?}: look at Primitive::intersect."
    );
}

#[test]
fn a_ray_hits_a_plane_at_minus_o_dot_n_plus_d_over_d_dot_n() {
    // The floor y = -1 from (1, 2, 3) along (0, -3, -4): O.N + d = 3 and D.N = -3/5, so t = 5; not
    // if the ray reaches only 4, or goes straight up, away from it.
    let floor = floor_plane();
    let origin = dvec3(1.0, 2.0, 3.0);
    let found = [
        hit(&floor, origin, dvec3(0.0, -3.0, -4.0), f64::INFINITY),
        hit(&floor, origin, dvec3(0.0, -3.0, -4.0), 4.0),
        hit(&floor, origin, UP, f64::INFINITY),
    ];
    assert!(
        found == [Some(5.0), None, None],
        "these rays should hit the floor at t = 5, and miss it with a reach of 4 and going up, not at {found:?}: look at Primitive::intersect."
    );
}
