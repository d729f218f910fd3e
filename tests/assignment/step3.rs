//! Step 3: a Primitive class, and derived from it a Sphere and a Plane class.
use super::*;

#[test]
fn a_scene_holds_spheres_and_planes_alike() {
    // A red ball over the white floor: the middle pixel sees the ball, the bottom one the floor.
    let frame = frame(
        vec![floor(), ball(5.0 * AHEAD, 1.0, RED, 0.0)],
        UP,
        Camera::default(),
    );
    let [ball, floor] = [MIDDLE, (VIEW / 2, VIEW - 1)].map(|pixel| rgb(&frame, pixel));
    assert!(
        is_red(ball) && floor[0] == floor[2] && floor[0] > 0,
        "the middle pixel should show the red ball and the bottom one the white floor, not RGB {ball:?} and {floor:?}: look at enum Primitive and Scene's objects."
    );
}
