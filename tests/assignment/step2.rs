//! Step 2: a Ray class: p(t) = O + tD, D normalized, 0 < t < ray.t.
use super::*;

#[test]
fn a_ray_holds_its_origin_its_unit_direction_and_how_far_it_reaches() {
    let ray = Ray::new(vec3(1.0, 2.0, 3.0), vec3(0.0, 3.0, -4.0), 7.0);
    let [origin, direction] = [ray.origin, ray.direction].map(to_dvec3);
    let unit = dvec3(0.0, 3.0, -4.0) / 5.0; // over its length, 5
    assert!(
        origin == dvec3(1.0, 2.0, 3.0) && direction.abs_diff_eq(unit, 1e-12) && ray.t == 7.0,
        "Ray::new((1, 2, 3), (0, 3, -4), 7) should hold O = (1, 2, 3), D = {unit} and t = 7, not {origin}, {direction} and {}: look at Ray::new and normalize.",
        ray.t
    );
}
