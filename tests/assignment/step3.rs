//! Step 3: a Primitive class, and derived from it a Sphere and a Plane class.
use super::*;

#[test]
fn a_scene_holds_spheres_and_planes_alike() {
    // A red ball 5 ahead over the white floor, seen from the start: the pixel of the ball's centre
    // shows the ball, red; that of the floor 2 ahead the floor, as red as it is blue (the sky is
    // bluer).
    let objects = vec![checkered_floor(), ball(5.0 * AHEAD, 1.0, RED, 0.0)];
    let frame = rendered(objects, UP, Camera::default());
    let [sphere, plane] = [5.0 * AHEAD, dvec3(0.0, -1.0, -2.0)]
        .map(|point| rgb(&frame, pixel_of(Camera::default(), point)));
    assert!(
        is_red(sphere) && plane.x == plane.z && plane.x > 0.0,
        "the ball's centre should show the red ball and the floor 2 ahead the white floor, not {sphere} and {plane}: look at enum Primitive and Scene's objects."
    );
}
