//! Step 1: a Camera class; by default at (0, 0, 0), looking at (0, 0, -1).
use super::*;

#[test]
fn the_default_camera_looks_from_0_0_0_at_0_0_minus_1() {
    let ray = Camera::default().primary_ray(HALF, HALF); // through the screen's centre
    let [origin, direction] = [ray.origin, ray.direction].map(to_dvec3);
    assert!(
        origin == ORIGIN && direction.abs_diff_eq(AHEAD, 1e-12),
        "the default camera's ray through the screen's centre should leave (0, 0, 0) along (0, 0, -1), not {origin} along {direction}: look at Camera's default and heading."
    );
}
