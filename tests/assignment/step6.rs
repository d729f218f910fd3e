//! Step 6: per pixel, the nearest intersection, and its colour plotted.
use super::*;

#[test]
fn the_nearest_hit_is_the_first_object_met_at_p_equals_o_plus_t_d() {
    // Straight down from (1, 2, 3), a ball listed before the floor: the ray meets the ball first,
    // at t = 1.5 and P = (1, 0.5, 3).
    let mut ray = Ray::new(vec3(1.0, 2.0, 3.0), vec3(0.0, -1.0, 0.0), f64::INFINITY);
    let scene = scene(vec![ball(dvec3(1.0, 0.0, 3.0), 0.5, RED, 0.0), floor()], UP);
    let point = scene.nearest_hit(&mut ray).map(|hit| to_dvec3(hit.point));
    assert!(
        point == Some(dvec3(1.0, 0.5, 3.0)) && ray.t == 1.5,
        "from (1, 2, 3) straight down, the nearest hit is the ball, at t = 1.5 and P = (1, 0.5, 3), not at t = {} and {point:?}: look at Scene::nearest_hit.",
        ray.t
    );
}

#[test]
fn each_pixel_shows_what_the_ray_through_its_centre_meets() {
    // A ball 0.01 in radius 6 out, on the ray through the centre of a pixel up and to the left:
    // that pixel shows it; where a picture flipped would put it, the sky.
    let (x, y) = (VIEW / 4, VIEW / 3);
    let center = through(Camera::default(), x as f64 + 0.5, y as f64 + 0.5).normalize() * 6.0;
    let frame = frame(
        vec![ball(center, 0.01, RED, 0.0)],
        ORIGIN,
        Camera::default(),
    );
    let flipped = [(VIEW - 1 - x, y), (x, VIEW - 1 - y), (y, x)].map(|pixel| rgb(&frame, pixel));
    assert!(
        is_red(rgb(&frame, (x, y))) && flipped == [bytes(SKY); 3],
        "pixel ({x}, {y}) should show the red ball its centre's ray meets, and the sky where a flipped picture would put it, not {flipped:?}: look at render, which traces the ray through each pixel's centre."
    );
}

#[test]
fn a_colour_brighter_than_white_shows_as_255() {
    // A ball of colour (0, 0.3, 2) lit head on, fully: its blue shows as 1, not carried into green.
    let glowing = ball(4.0 * AHEAD, 1.0, dvec3(0.0, 0.3, 2.0), 0.0);
    let seen = rgb(&frame(vec![glowing], ORIGIN, Camera::default()), MIDDLE);
    assert!(
        seen == bytes(dvec3(0.0, 0.3, 1.0)),
        "a colour (0, 0.3, 2) should show as (0, 0.3, 1), not RGB {seen:?}: look at to_rgb."
    );
}
