//! Step 3: a Primitive class, and derived from it a Sphere and a Plane class.
use super::*;

#[test]
fn a_scene_holds_spheres_and_planes_alike() {
    // A red ball over the white floor: the middle pixel sees the ball, the bottom one the floor.
    let objects = vec![checkered_floor(), ball(5.0 * AHEAD, 1.0, RED, 0.0)];
    let frame = rendered(objects, UP, Camera::default());
    let [sphere, plane] = [MIDDLE, (VIEW / 2, VIEW - 1)].map(|pixel| rgb(&frame, pixel));
    let [red, green, blue] = plane;
    assert!(
        is_red(sphere) && red == green && green == blue && red > 0,
        "the middle pixel should show the red ball and the bottom one the white floor, not RGB {sphere:?} and {plane:?}: look at enum Primitive and Scene's objects."
    );
}
