//! Pixel tests of the headless `render`: the expectations are worked out here from the geometry,
//! with the test's own projection, ray-sphere quadratic and reflection, not by calling the code
//! under test; the few that compare its output with its own output in another case say "compares".
#[allow(dead_code)]
#[path = "../src/main.rs"]
mod raytracer;

use raytracer::*;

const RED: Vec3 = vec3(0.9, 0.1, 0.1);
const SKY: Vec3 = vec3(0.4, 0.6, 1.0);
const WHITE: Vec3 = vec3(1.0, 1.0, 1.0);
const PURE_RED: Vec3 = vec3(1.0, 0.0, 0.0); // its outline on the map is 0xff0000 exactly
const PURE_GREEN: Vec3 = vec3(0.0, 1.0, 0.0);
/// A floor square's green byte is under this where the square is odd: odd squares show at most a
/// quarter of 255 (63), and the even ones these tests look at, lit from high up, 125 or more.
const ODD_BELOW: u32 = 100;
const HALF_VIEW: f64 = VIEW as f64 / 2.0; // the screen's middle, in pixels from an edge

fn matte(color: Vec3) -> Material {
    Material {
        color,
        reflectivity: 0.0,
        checkered: false,
    }
}

fn sphere(center: Vec3, radius: f64, material: Material) -> (Shape, Material) {
    (Shape::Sphere { center, radius }, material)
}

/// The floor's height, as in the demo.
const FLOOR_Y: f64 = -1.0;

/// A white checkered floor y = FLOOR_Y: the plane p.N + d = 0 with N = (0, 1, 0), d = -FLOOR_Y.
fn checkered_floor() -> (Shape, Material) {
    let checkered = Material {
        color: WHITE,
        reflectivity: 0.0,
        checkered: true,
    };
    (
        Shape::Plane {
            normal: vec3(0.0, 1.0, 0.0),
            offset: -FLOOR_Y,
        },
        checkered,
    )
}

/// A pixel counts as red where its red byte is over this many times its green and its blue: a
/// RED ball shows 9 times, however lit; the sky and the floor never more than once.
const RED_OVER: u32 = 2;

fn is_red([r, g, b]: [u32; 3]) -> bool {
    r > RED_OVER * g && r > RED_OVER * b
}

fn scene_of(objects: Vec<(Shape, Material)>, light: Vec3) -> Scene {
    Scene {
        objects,
        light,
        sky: SKY,
    }
}

fn frame_of(scene: &Scene, camera: &Camera) -> Vec<u32> {
    let mut frame = vec![0; WIDTH * VIEW];
    render(scene, camera, &mut frame);
    frame
}

/// The 3D view's pixel (x, y) as [red, green, blue] bytes.
fn rgb(frame: &[u32], (x, y): (usize, usize)) -> [u32; 3] {
    let pixel = frame[y * WIDTH + x];
    [pixel >> 16 & 255, pixel >> 8 & 255, pixel & 255]
}

/// A colour channel from 0 to 1 as a byte, 0 to 255.
fn byte(channel: f64) -> u32 {
    (channel * 255.0) as u32
}

/// A colour as [red, green, blue] bytes.
fn bytes(color: Vec3) -> [u32; 3] {
    [byte(color.x), byte(color.y), byte(color.z)]
}

/// A colour as a 0RGB pixel, as the map draws an outline.
fn pixel_of(color: Vec3) -> u32 {
    let [red, green, blue] = bytes(color);
    red << 16 | green << 8 | blue
}

/// The share of the light a surface gets even in shadow, as the README gives it.
const AMBIENT: f64 = 0.1;

/// Diffuse shading with an ambient share, as the README gives it: ambient + (1 - ambient) N.L,
/// where N.L <= 0 (the light behind the surface) adds nothing.
fn lit_share(point: Vec3, normal: Vec3, light: Vec3) -> f64 {
    let n_dot_l = normal.dot((light - point).normalize());
    AMBIENT + (1.0 - AMBIENT) * n_dot_l.max(0.0)
}

/// A pixel's centre sees a point up to half a pixel from the one the test projects, where N.L
/// differs by up to about 0.01 on these surfaces: 3 of 255 levels.
const SHADING_SLACK: u32 = 3;

fn cross(a: Vec3, b: Vec3) -> Vec3 {
    vec3(
        a.y * b.z - a.z * b.y,
        a.z * b.x - a.x * b.z,
        a.x * b.y - a.y * b.x,
    )
}

/// The camera's view, right and up directions: it looks along
/// (-sin yaw cos pitch, sin pitch, -cos yaw cos pitch), right is level, up is right x view.
fn camera_axes(camera: &Camera) -> (Vec3, Vec3, Vec3) {
    let Camera { yaw, pitch, .. } = *camera;
    let view = vec3(
        -yaw.sin() * pitch.cos(),
        pitch.sin(),
        -yaw.cos() * pitch.cos(),
    );
    let right = vec3(yaw.cos(), 0.0, -yaw.sin());
    (view, right, cross(right, view))
}

/// Where a world point shows in the 3D view: the screen is 1 ahead of the eye, 2 wide and 2 high.
fn project(camera: &Camera, point: Vec3) -> (usize, usize) {
    let (view, right, up) = camera_axes(camera);
    let d = point - camera.position;
    let across = d.dot(right) / d.dot(view); // from -1 at the left edge to 1 at the right
    let upward = d.dot(up) / d.dot(view); // from -1 at the bottom to 1 at the top
    // Not a check of the program: a test whose point is off screen would read the wrong pixel.
    assert!(
        d.dot(view) > 0.0 && across.abs() < 1.0 && upward.abs() < 1.0,
        "{point:?} is off screen"
    );
    let column = (across + 1.0) * HALF_VIEW;
    let row = (1.0 - upward) * HALF_VIEW;
    (column as usize, row as usize)
}

/// Does the segment a-b pass through the sphere?
fn segment_hits_sphere(a: Vec3, b: Vec3, center: Vec3, radius: f64) -> bool {
    let ab = b - a;
    let t = ((center - a).dot(ab) / ab.dot(ab)).clamp(0.0, 1.0);
    let closest = a + ab * t - center;
    closest.dot(closest) < radius * radius
}

fn odd_square(point: Vec3) -> bool {
    (point.x.floor() as i64 + point.z.floor() as i64) & 1 == 1 // the slide's F, with floor
}

#[test]
fn sky_pixels_are_the_sky_colour() {
    let scene = scene_of(
        vec![sphere(vec3(0.0, 0.0, -4.0), 1.0, matte(RED))],
        vec3(0.0, 5.0, 0.0),
    );
    let frame = frame_of(&scene, &Camera::default());
    let sky = bytes(SKY);
    let last = VIEW - 1;
    let above_the_ball = project(&Camera::default(), vec3(0.0, 2.0, -4.0));
    for pixel in [(0, 0), (last, 0), (0, last), (last, last), above_the_ball] {
        assert_eq!(rgb(&frame, pixel), sky, "pixel {pixel:?}");
    }
}

#[test]
fn a_sphere_covers_its_projected_centre_and_not_past_its_silhouette() {
    let center = vec3(1.0, 0.5, -5.0);
    let radius = 1.0;
    let scene = scene_of(
        vec![sphere(center, radius, matte(RED))],
        vec3(0.0, 0.0, 0.0),
    );
    let camera = Camera::default();
    let frame = frame_of(&scene, &camera);
    let centre = rgb(&frame, project(&camera, center));
    assert!(is_red(centre), "centre is {centre:?}, not red");
    // The silhouette seen from the eye is a cone of half-angle asin(r / distance): step past it.
    let distance = center.length();
    let half_angle = (radius / distance).asin() + 0.02; // 0.02 radians past it: 5 pixels
    let toward = center.normalize();
    let beside = vec3(toward.z, 0.0, -toward.x).normalize(); // level, at right angles to `toward`
    let outside = (toward * half_angle.cos() + beside * half_angle.sin()) * distance;
    let sky = bytes(SKY);
    assert_eq!(rgb(&frame, project(&camera, outside)), sky);
}

#[test]
fn a_sphere_is_shaded_by_n_dot_l_on_the_side_facing_the_light() {
    let center = vec3(0.0, 0.0, -4.0);
    let light = vec3(-10.0, 0.0, -4.0);
    let scene = scene_of(vec![sphere(center, 1.0, matte(RED))], light);
    let camera = Camera::default();
    let frame = frame_of(&scene, &camera);
    // Two points on the sphere's front, on the left facing the light and on the right facing away.
    let slant = std::f64::consts::FRAC_1_SQRT_2;
    for normal in [vec3(-slant, 0.0, slant), vec3(slant, 0.0, slant)] {
        let point = center + normal;
        let red = rgb(&frame, project(&camera, point))[0];
        let expected = byte(RED.x * lit_share(point, normal, light));
        assert!(
            red.abs_diff(expected) <= SHADING_SLACK,
            "{normal:?}: {red}, not {expected}"
        );
    }
}

#[test]
fn a_sphere_between_floor_and_light_casts_a_shadow() {
    let center = vec3(0.0, 0.0, -5.0);
    let light = vec3(0.0, 3.0, -5.0);
    let scene = scene_of(
        vec![checkered_floor(), sphere(center, 1.0, matte(RED))],
        light,
    );
    let camera = Camera {
        position: vec3(0.0, 1.0, 0.0),
        pitch: -0.3,
        yaw: 0.0,
    };
    let frame = frame_of(&scene, &camera);
    // Two floor points on even squares, both seen from the eye (their sight lines pass the ball's
    // centre 1.37 and 2.65 away): the segment from the first to the light passes the centre 0.69
    // away, inside the ball, so it gets only the ambient light; the second's passes 1.65 away.
    let shaded = vec3(-0.5, FLOOR_Y, -4.2);
    let lit = vec3(-2.5, FLOOR_Y, -4.2);
    let up = vec3(0.0, 1.0, 0.0);
    for (point, share) in [(shaded, AMBIENT), (lit, lit_share(lit, up, light))] {
        let green = rgb(&frame, project(&camera, point))[1];
        let expected = byte(WHITE.y * share);
        assert!(
            green.abs_diff(expected) <= SHADING_SLACK,
            "{point:?}: {green}, not {expected}"
        );
    }
}

#[test]
fn only_occluders_between_the_point_and_the_light_cast_shadows() {
    // (compares) The floor with two balls that cast no shadow on it against the floor alone.
    // A ball above the light, and one beside it: neither lies between the floor and the light.
    let light = vec3(0.0, 2.0, -4.0);
    let above = sphere(vec3(0.0, 4.0, -4.0), 1.0, matte(RED));
    let beside = sphere(vec3(4.0, 0.0, -8.0), 1.0, matte(RED));
    let camera = Camera {
        position: vec3(0.0, 1.0, 0.0),
        pitch: -0.3,
        yaw: 0.0,
    };
    let lit = frame_of(&scene_of(vec![checkered_floor()], light), &camera);
    let with_balls = frame_of(
        &scene_of(vec![checkered_floor(), above, beside], light),
        &camera,
    );
    let point = project(&camera, vec3(0.5, FLOOR_Y, -3.5));
    assert_eq!(rgb(&with_balls, point), rgb(&lit, point));
}

#[test]
fn the_floor_is_checkered_by_floor_x_plus_floor_z() {
    let scene = scene_of(vec![checkered_floor()], vec3(0.0, 100.0, 0.0));
    let camera = Camera {
        position: vec3(0.0, 1.0, 3.0),
        pitch: -0.5,
        yaw: 0.0,
    };
    let frame = frame_of(&scene, &camera);
    // Square centres on both sides of x = 0 and of z = 0.
    for x in [-1.5, -0.5, 0.5, 1.5] {
        for z in [-1.5, -0.5, 0.5, 1.5] {
            let point = vec3(x, FLOOR_Y, z);
            let green = rgb(&frame, project(&camera, point))[1];
            assert_eq!(
                green < ODD_BELOW,
                odd_square(point),
                "square at {point:?} is {green}"
            );
        }
    }
}

/// Where the mirror sphere's pixel (x, y) sends its reflected ray, by the test's own geometry:
/// the point it hits the unit sphere at `center` and the reflected direction, if it hits.
fn reflected_ray(eye: Vec3, center: Vec3, (x, y): (usize, usize)) -> Option<(Vec3, Vec3)> {
    let across = (x as f64 + 0.5) / HALF_VIEW - 1.0;
    let upward = 1.0 - (y as f64 + 0.5) / HALF_VIEW;
    let d = vec3(across, upward, -1.0).normalize(); // a camera looking down -z, at any `eye`
    let point = ray_sphere(eye, d, center, 1.0)?;
    let n = point - center;
    Some((point, d - n * (2.0 * d.dot(n))))
}

#[test]
fn a_mirror_sphere_reflects_the_checkered_floor_and_the_sky() {
    let center = vec3(0.0, 0.0, -4.0);
    let mirror = Material {
        color: WHITE,
        reflectivity: 1.0,
        checkered: false,
    };
    let light = vec3(0.0, 20.0, 20.0);
    let scene = scene_of(vec![checkered_floor(), sphere(center, 1.0, mirror)], light);
    let camera = Camera::default();
    let frame = frame_of(&scene, &camera);
    let sky = bytes(SKY);
    // Every 4th pixel of the view each way; those that miss the ball are passed over. Of those that
    // hit it, 418 reflect the sky, 163 an odd square and 160 an even one; the others see the floor
    // near a square's edge or in the ball's shadow.
    for y in (0..VIEW).step_by(4) {
        for x in (0..VIEW).step_by(4) {
            let Some((point, direction)) = reflected_ray(camera.position, center, (x, y)) else {
                continue;
            };
            if direction.y >= 0.0 {
                assert_eq!(rgb(&frame, (x, y)), sky, "pixel {x}, {y} reflects the sky");
                continue;
            }
            let on_floor = point + direction * ((FLOOR_Y - point.y) / direction.y);
            let near_edge = |w: f64| (w - w.round()).abs() < 0.05; // within 0.05 units of it
            if near_edge(on_floor.x) || near_edge(on_floor.z) {
                continue; // too near a square's edge to say which square the pixel shows
            }
            if segment_hits_sphere(on_floor, light, center, 1.0) {
                continue; // in the ball's shadow: dark either way
            }
            let green = rgb(&frame, (x, y))[1];
            let odd = odd_square(on_floor);
            assert_eq!(green < ODD_BELOW, odd, "pixel {x}, {y}: {green}");
        }
    }
}

#[test]
fn a_part_mirror_mixes_its_own_colour_with_what_its_mirror_ray_sees() {
    // A grey wall z = -5 facing the eye, a quarter mirror, lit from the eye: the pixel at the
    // centre shows three quarters of the wall's own lit colour and a quarter of what its mirror ray
    // sees going straight back past the eye: the sky.
    let reflectivity = 0.25;
    let grey = vec3(0.6, 0.6, 0.6);
    let facing_the_eye = vec3(0.0, 0.0, 1.0);
    let wall = Shape::Plane {
        normal: facing_the_eye,
        offset: 5.0, // p.N + d = z + 5 = 0
    };
    let part_mirror = Material {
        color: grey,
        reflectivity,
        checkered: false,
    };
    let camera = Camera::default();
    let scene = scene_of(vec![(wall, part_mirror)], camera.position);
    let frame = frame_of(&scene, &camera);
    // The centre pixel sees the wall within 0.03 of (0, 0, -5), where N.L is 1 within 10^-4.
    let lit = lit_share(vec3(0.0, 0.0, -5.0), facing_the_eye, camera.position);
    let expected = bytes(grey * (lit * (1.0 - reflectivity)) + SKY * reflectivity);
    let shown = rgb(&frame, (VIEW / 2, VIEW / 2));
    for (channel, name) in ["red", "green", "blue"].iter().enumerate() {
        assert!(
            shown[channel].abs_diff(expected[channel]) <= SHADING_SLACK,
            "{name}: {shown:?}, not {expected:?}"
        );
    }
}

#[test]
fn turning_and_moving_the_camera_move_the_image() {
    let ball = vec3(-3.0, 0.0, -1.5);
    let scene = scene_of(vec![sphere(ball, 0.5, matte(RED))], vec3(0.0, 5.0, 0.0));
    // Straight ahead is -z; the ball is far to the left, out of view: after a quarter turn left
    // the view looks down -x, the ball is 3 ahead and 1.5 right: half way to the right edge.
    let turned = Camera {
        yaw: std::f64::consts::FRAC_PI_2,
        ..Camera::default()
    };
    let beside = project(&turned, ball);
    let turned_frame = frame_of(&scene, &turned);
    assert!(is_red(rgb(&turned_frame, beside)), "turned: the ball");
    let ahead_frame = frame_of(&scene, &Camera::default());
    assert!(!is_red(rgb(&ahead_frame, beside)), "not turned: no ball");
    // Stepping to z = -1.5 puts the ball dead ahead of the turned camera.
    let moved = Camera {
        position: vec3(0.0, 0.0, -1.5),
        ..turned
    };
    let moved_frame = frame_of(&scene, &moved);
    assert!(
        is_red(rgb(&moved_frame, project(&moved, ball))),
        "moved: the ball ahead"
    );
    assert!(
        !is_red(rgb(&moved_frame, beside)),
        "moved: no ball to the right"
    );
}

/// The 2D map: x to the right from MAP_CORNER.x, z down from MAP_CORNER.z, MAP_SCALE pixels a unit.
fn map_pixel(frame: &[u32], x: f64, z: f64) -> u32 {
    let column = ((x - MAP_CORNER.x) * MAP_SCALE) as usize;
    let row = ((z - MAP_CORNER.z) * MAP_SCALE) as usize;
    frame[row * WIDTH + VIEW + column]
}

/// Is a square drawn around a world point: all map pixels within `radius` of its pixel in `color`?
/// A hit's dot has radius 1 (3 x 3), a marker 3 (7 x 7); a line through them colours only some.
fn square_at(frame: &[u32], point: Vec3, radius: i32, color: u32) -> bool {
    map_near(frame, point, radius)
        .iter()
        .all(|&pixel| pixel == color)
}

/// The map pixels within `pixels` map pixels of a world point's x and z (those on the map).
fn map_near(frame: &[u32], point: Vec3, pixels: i32) -> Vec<u32> {
    let mut found = Vec::new();
    for dx in -pixels..=pixels {
        for dz in -pixels..=pixels {
            let x = point.x + dx as f64 / MAP_SCALE;
            let z = point.z + dz as f64 / MAP_SCALE;
            let on_map = |w: f64, low: f64| (low..low + VIEW as f64 / MAP_SCALE).contains(&w);
            if on_map(x, MAP_CORNER.x) && on_map(z, MAP_CORNER.z) {
                found.push(map_pixel(frame, x, z));
            }
        }
    }
    found
}

#[test]
fn the_slice_shows_the_camera_the_light_a_sphere_outline_and_the_sampled_rays() {
    let center = vec3(2.0, 0.0, -5.0);
    let light = vec3(0.0, 5.0, 2.0);
    let scene = scene_of(vec![sphere(center, 1.0, matte(PURE_RED))], light);
    let frame = frame_of(&scene, &Camera::default());
    assert_eq!(map_pixel(&frame, 0.0, 0.0), CAMERA_COLOR, "the camera dot");
    // The light's marker, a square 7 map pixels wide, is all there around the light's x and z.
    assert!(square_at(&frame, light, 3, LIGHT_COLOR), "the light");
    // The screen's middle row, from x = -1 to 1 at z = -1 (d = 1 ahead), and not past its ends.
    for x in [-0.5, 0.5] {
        assert_eq!(
            map_pixel(&frame, x, -1.0),
            CAMERA_COLOR,
            "the screen at {x}"
        );
    }
    for x in [-1.05, 1.05] {
        assert_ne!(
            map_pixel(&frame, x, -1.0),
            CAMERA_COLOR,
            "past the screen at {x}"
        );
    }
    // The far side of the outline, hidden from the rays by the sphere itself: angles in radians
    // from +x towards -z.
    for angle in [1.2f64, 1.6, 2.0] {
        let x = center.x + angle.cos();
        let z = center.z - angle.sin();
        let near = map_near(&frame, vec3(x, 0.0, z), 1);
        assert!(
            near.contains(&pixel_of(PURE_RED)),
            "outline at {x}, {z}: {near:x?}"
        );
    }
    // The sampled rays that hit the sphere stop at its front: none is drawn on to its centre.
    // Within 2 map pixels of it, as the nearest ray to it (column 360's) passes 1.5 pixels away.
    let around_the_center = map_near(&frame, center, 2);
    assert!(
        !around_the_center.contains(&RAY_COLOR),
        "a ray past its hit"
    );
    // The sphere is matte: no mirror ray.
    assert!(
        !map_of(&frame).contains(&MIRROR_COLOR),
        "a matte sphere's mirror ray"
    );
    // The middle row's first ray leaves along about (-1, 0, -1) and hits nothing.
    for t in [2.0, 4.0, 6.0] {
        let near = map_near(&frame, vec3(-t, 0.0, -t), 1);
        assert!(near.contains(&MISS_COLOR), "the missing ray at {t}");
    }
    // On that ray at t = 3√2 something, and 0.4 units (16 map pixels) left of it nothing.
    assert_ne!(
        map_pixel(&frame, -3.0, -3.0),
        BACKGROUND,
        "on the missing ray"
    );
    assert_eq!(map_pixel(&frame, -3.4, -3.0), BACKGROUND, "beside the ray");
}

/// The right half of a frame: the 2D slice.
fn map_of(frame: &[u32]) -> Vec<u32> {
    frame
        .chunks(WIDTH)
        .flat_map(|row| row[VIEW..].to_vec())
        .collect()
}

#[test]
fn with_a_level_camera_the_slice_rays_stay_in_the_eyes_plane() {
    // (compares) Rays through the screen's middle row of a level camera are horizontal: they
    // never meet a floor below (or above) the eye, so a floor changes nothing on the map.
    // Five chosen poses, one where rounding once sent middle-row rays into the floor 1e16 away,
    // and 40 more spread around the demo: each coordinate steps by its own amount and wraps
    // around its range, so that no two poses repeat.
    let spread = (0..40).map(|step| {
        let i = f64::from(step);
        let position = vec3(
            (i * 0.37) % 5.0 - 2.5, // x from -2.5 to 2.5
            (i * 0.23) % 3.0 - 0.5, // y from -0.5 to 2.5: always above the floor y = -1
            (i * 0.61) % 4.0 - 2.0, // z from -2 to 2
        );
        let yaw = i * 0.29 - 5.0; // from -5 to 6.3 radians: all the way round and more
        (position, yaw)
    });
    let chosen = [
        (vec3(0.0, 0.0, 0.0), 0.0),     // the start pose
        (vec3(0.7, 0.3, -1.0), 0.4),    // among the balls, turned a little left
        (vec3(-1.0, 2.5, 1.0), -2.0),   // high up, turned right and past a quarter turn
        (vec3(0.0, -3.0, 0.0), 1.0),    // below the floor
        (vec3(-1.9, 0.18, 0.07), 0.03), // where rounding once sent the rays into the floor
    ];
    for (position, yaw) in chosen.into_iter().chain(spread) {
        let camera = Camera {
            position,
            yaw,
            pitch: 0.0,
        };
        let light = vec3(0.0, 5.0, 0.0);
        let empty = frame_of(&scene_of(vec![], light), &camera);
        let floor_only = frame_of(&scene_of(vec![checkered_floor()], light), &camera);
        assert!(
            map_of(&empty) == map_of(&floor_only),
            "{position:?}, yaw {yaw}"
        );
    }
}

#[test]
fn a_sphere_cut_by_the_eyes_plane_shows_the_hits_on_its_outline() {
    // Centre half a unit below the eye: the plane y = 0 cuts it in a circle of radius sqrt(0.75).
    let center = vec3(0.0, -0.5, -4.0);
    let scene = scene_of(
        vec![checkered_floor(), sphere(center, 1.0, matte(RED))],
        vec3(0.0, 5.0, 2.0),
    );
    let frame = frame_of(&scene, &Camera::default());
    let cut = 0.75f64.sqrt();
    // 12 of the 52 sampled rays hit it.
    for x in (0..VIEW).step_by(10) {
        // Column x's sampled ray, in the plane y = 0, meets the circle where |O + tD - C| = cut.
        let d = vec3((x as f64 + 0.5) / HALF_VIEW - 1.0, 0.0, -1.0).normalize();
        let to_center = vec3(center.x, 0.0, center.z);
        let t_center = to_center.dot(d);
        let p2 = to_center.dot(to_center) - t_center * t_center;
        if p2 >= cut * cut - 1e-3 {
            continue; // misses, or only grazes, the circle (p² within 0.001 of its r²)
        }
        let hit = d * (t_center - (cut * cut - p2).sqrt());
        assert!(
            square_at(&frame, hit, 1, RAY_COLOR),
            "no hit dot at {hit:?}, column {x}"
        );
    }
}

#[test]
fn odd_cameras_render_valid_frames() {
    // A scene like the demo: the checkered floor, a mirror ball and the light up to the left.
    let ball_center = vec3(0.3, 0.0, -4.5);
    let mirror = Material {
        color: WHITE,
        reflectivity: 0.85,
        checkered: false,
    };
    let objects = vec![checkered_floor(), sphere(ball_center, 1.0, mirror)];
    let scene = scene_of(objects, vec3(-3.0, 5.0, 1.0));
    let inside = Camera {
        position: ball_center,
        ..Camera::default()
    };
    let inside_frame = frame_of(&scene, &inside);
    // From the centre of the mirror ball every ray meets its inside, never the sky.
    let sky = bytes(SKY);
    for y in 0..VIEW {
        for x in 0..VIEW {
            assert_ne!(rgb(&inside_frame, (x, y)), sky, "pixel {x}, {y}");
        }
    }
    // Below the floor, looking up at it: its underside faces away from the light, so an even
    // square there gets only the ambient light.
    let below = Camera {
        position: vec3(0.0, -3.0, 0.0),
        pitch: 1.0,
        yaw: 0.0,
    };
    let below_frame = frame_of(&scene, &below);
    let even_square = vec3(0.5, FLOOR_Y, -1.5);
    let underside_green = rgb(&below_frame, project(&below, even_square))[1];
    assert_eq!(underside_green, byte(WHITE.y * AMBIENT));
    let down = Camera {
        pitch: -std::f64::consts::FRAC_PI_2,
        ..Camera::default()
    };
    let down_frame = frame_of(&scene, &down);
    // Straight down from y = 0 the view is the floor: an even and an odd square's centre.
    for point in [vec3(0.5, FLOOR_Y, 0.5), vec3(-0.5, FLOOR_Y, 0.5)] {
        let green = rgb(&down_frame, project(&down, point))[1];
        assert_eq!(green < ODD_BELOW, odd_square(point), "{point:?}: {green}");
    }
}

/// Where a ray O + tD from outside a sphere first meets it, by the quadratic |O + tD - C|² = r²:
/// the near root, if it is in front (none of the tests' rays starts inside a sphere).
fn ray_sphere(origin: Vec3, direction: Vec3, center: Vec3, radius: f64) -> Option<Vec3> {
    let d = direction.normalize();
    let oc = origin - center;
    let half_b = oc.dot(d);
    let c = oc.dot(oc) - radius * radius;
    let discriminant = half_b * half_b - c;
    if discriminant < 0.0 {
        return None; // the line passes the sphere by
    }
    let t = -half_b - discriminant.sqrt();
    (t > 0.0).then(|| origin + d * t)
}

/// The sampled rays of the slice: every 10th column of the screen's middle row, by the test's own
/// camera geometry (the screen 1 ahead, 2 wide).
fn sampled_directions(camera: &Camera) -> Vec<Vec3> {
    let (view, right, _) = camera_axes(camera);
    (0..VIEW)
        .step_by(10)
        .map(|x| view + right * ((x as f64 + 0.5) / HALF_VIEW - 1.0))
        .collect()
}

#[test]
fn a_pitched_slice_plane_outlines_the_spheres_it_cuts_and_no_others() {
    for (yaw, pitch) in [
        (0.0, 0.25),
        (0.0, -0.25),
        (0.6, 0.3),
        (-0.9, -0.35),
        (1.3, -0.2),
    ] {
        let camera = Camera {
            position: vec3(0.5, 0.3, 1.0),
            yaw,
            pitch,
        };
        let (view, right, up) = camera_axes(&camera);
        let eye = camera.position;
        // Cut: its centre 0.4 above the tilted plane, so the plane cuts it in a circle of
        // radius sqrt(r² - 0.4²) around the centre's foot on the plane.
        let cut_radius: f64 = 1.0;
        let height = 0.4;
        let cut_center = eye + view * 5.0 + right * 0.5 + up * height;
        let foot = cut_center - up * height;
        let circle = (cut_radius * cut_radius - height * height).sqrt();
        // Missed: at the eye's height, which a level plane would cut, but 5 |sin pitch| >= 0.99
        // from the tilted plane (level_view.up = -sin pitch, right.up = 0), further than its
        // radius 0.8.
        let level_view = vec3(-yaw.sin(), 0.0, -yaw.cos());
        let missed_center = eye + level_view * 5.0 - right * 2.5;
        let scene = scene_of(
            vec![
                sphere(cut_center, cut_radius, matte(PURE_RED)),
                sphere(missed_center, 0.8, matte(PURE_GREEN)),
            ],
            eye - view * 3.0 + up * 4.0,
        );
        let frame = frame_of(&scene, &camera);
        let case = format!("yaw {yaw}, pitch {pitch}");
        // The far side of the outline, where no sampled ray ends.
        for angle in [1.2f64, 1.57, 1.9] {
            let on_outline = foot + (right * angle.cos() + view * angle.sin()) * circle;
            let near = map_near(&frame, on_outline, 1);
            assert!(
                near.contains(&pixel_of(PURE_RED)),
                "{case}: outline at {on_outline:?}"
            );
        }
        let map = map_of(&frame);
        assert!(
            !map.contains(&pixel_of(PURE_GREEN)),
            "{case}: the missed sphere is outlined"
        );
        // Each sampled ray that hits the cut sphere hits it on the outline, and its dot is there
        // (9 of the 52 rays in each pose).
        for direction in sampled_directions(&camera) {
            let Some(hit) = ray_sphere(eye, direction, cut_center, cut_radius) else {
                continue;
            };
            assert!(
                square_at(&frame, hit, 1, RAY_COLOR),
                "{case}: no hit dot at {hit:?}"
            );
        }
    }
}

#[test]
fn from_far_off_the_map_the_sampled_rays_cross_it_up_to_their_hits() {
    let center = vec3(0.0, 0.0, -5.0);
    // The light straight above the sphere: no hit on the slice plane faces it, so no shadow ray is
    // drawn, and the sphere is matte, so no mirror ray either.
    let radius = 3.0;
    let scene = scene_of(
        vec![sphere(center, radius, matte(RED))],
        vec3(0.0, 20.0, -5.0),
    );
    for distance in [20.0, 30.0, 40.0] {
        let camera = Camera {
            position: vec3(0.0, 0.0, distance),
            ..Camera::default()
        };
        let frame = frame_of(&scene, &camera);
        // The map's bottom and top edges as depths z, and its width, each a little inside.
        let side = VIEW as f64 / MAP_SCALE;
        let inset = 0.4;
        let bottom = MAP_CORNER.z + side - inset;
        let top = MAP_CORNER.z + inset;
        let within_width =
            |point: Vec3| (MAP_CORNER.x + inset..MAP_CORNER.x + side - inset).contains(&point.x);
        // Of the sampled rays that cross the map from its bottom edge, 6, 4 and 4 hit the sphere
        // and 4, 4 and 2 miss it at the three distances.
        for direction in sampled_directions(&camera) {
            let d = direction.normalize();
            let at_z = |z: f64| camera.position + d * ((z - distance) / d.z); // the ray at depth z
            if !within_width(at_z(bottom)) {
                continue; // it passes beside the map
            }
            match ray_sphere(camera.position, direction, center, radius) {
                Some(hit) => {
                    let halfway = at_z((bottom + hit.z) / 2.0);
                    let just_before = at_z(hit.z + 0.3); // 0.3 units before the hit in depth
                    for point in [at_z(bottom), halfway, just_before] {
                        let near = map_near(&frame, point, 1);
                        assert!(near.contains(&RAY_COLOR), "{distance}: ray at {point:?}");
                    }
                }
                None if within_width(at_z(top)) => {
                    for point in [at_z(bottom), at_z((bottom + top) / 2.0), at_z(top)] {
                        let near = map_near(&frame, point, 1);
                        assert!(near.contains(&MISS_COLOR), "{distance}: miss at {point:?}");
                    }
                }
                None => {}
            }
        }
    }
}

#[test]
fn a_blocked_shadow_ray_ends_at_its_blocker() {
    let camera = Camera::default();
    let target = vec3(1.5, 0.0, -6.0);
    let target_radius = 1.0;
    let light = vec3(-3.0, 0.0, -3.0);
    // The leftmost sampled hit on the target sphere, on its side facing the light to the left, and
    // its shadow ray's segment to the light.
    let hit = sampled_directions(&camera)
        .into_iter()
        .filter_map(|d| ray_sphere(camera.position, d, target, target_radius))
        .min_by(|a, b| a.x.total_cmp(&b.x))
        .expect("a sampled ray hits the target"); // not a check of the program: of this set-up
    let to_light = (light - hit).normalize();
    // The blocker: a sphere of radius 0.3 half way along that segment.
    let blocker = hit + (light - hit) * 0.5;
    let objects = vec![
        sphere(target, target_radius, matte(RED)),
        sphere(blocker, 0.3, matte(RED)),
    ];
    let frame = frame_of(&scene_of(objects, light), &camera);
    let before = blocker - to_light * 0.45; // 0.15 before the blocker's surface
    let after = blocker + to_light * 0.7; // 0.4 past it, on the light's side
    assert!(
        map_near(&frame, before, 1).contains(&BLOCKED_COLOR),
        "before the blocker"
    );
    assert!(
        !map_near(&frame, after, 1).contains(&BLOCKED_COLOR),
        "past the blocker"
    );
}

// The map as a newcomer reads it: the sampled rays on top, every colour apart, the eye's marker.

/// The first sphere of the scene that a ray from `origin` along `direction` meets, by the test's
/// own quadratic: where, and the distance from the origin.
fn first_sphere_hit(scene: &Scene, origin: Vec3, direction: Vec3) -> Option<(Vec3, f64)> {
    let hits = scene.objects.iter().filter_map(|(shape, _)| match *shape {
        Shape::Sphere { center, radius } => ray_sphere(origin, direction, center, radius),
        Shape::Plane { .. } => None,
    });
    let nearest = hits.min_by(|a, b| (*a - origin).length().total_cmp(&(*b - origin).length()))?;
    Some((nearest, (nearest - origin).length()))
}

/// Is the world point's x and z on the map, at least `margin` units inside its edges?
fn inside_map(point: Vec3, margin: f64) -> bool {
    let span = VIEW as f64 / MAP_SCALE;
    let inside = |w: f64, low: f64| w > low + margin && w < low + span - margin;
    inside(point.x, MAP_CORNER.x) && inside(point.z, MAP_CORNER.z)
}

/// Of the points along the sampled rays, at most this share may show another colour than the ray's:
/// where a point falls between a ray's dots, what lies below may show (under 1% today), while the
/// shadow rays drawn over the sampled ones showed at 9% in the start pose and 11% close.
const MOST_COVERED: f64 = 0.02;
/// And at least this share shows the ray's own colour (90% today); the rest is black, where a point
/// falls on the map pixel beside a one-pixel line.
const LEAST_ON_RAY: f64 = 0.85;

#[test]
fn the_sampled_rays_are_on_top_along_their_whole_length() {
    let scene = Scene::default();
    // The start pose, and the eye close to the balls, where the most shadow rays cross the fan.
    for position in [vec3(0.0, 0.0, 0.0), vec3(0.0, 0.0, -1.5)] {
        let camera = Camera {
            position,
            ..Camera::default()
        };
        let frame = frame_of(&scene, &camera);
        let mut on_ray = 0;
        let mut covered = 0;
        let mut checked = 0;
        for direction in sampled_directions(&camera) {
            let d = direction.normalize();
            let hit = first_sphere_hit(&scene, position, d);
            let color = if hit.is_some() { RAY_COLOR } else { MISS_COLOR };
            // Where to stop: 0.05 units (2 map pixels) before the hit's dot, or at the map's edge.
            let end = hit.map_or(f64::INFINITY, |(_, distance)| distance - 0.05);
            // From past the screen's middle row (1 to √2 ahead) to the hit or the map's edge, every
            // half map pixel.
            let mut t = 1.5;
            while t < end {
                let point = position + d * t;
                t += 0.5 / MAP_SCALE;
                if !inside_map(point, 0.0) {
                    break;
                }
                let pixel = map_pixel(&frame, point.x, point.z);
                checked += 1;
                if pixel == color {
                    on_ray += 1;
                } else if pixel != BACKGROUND {
                    covered += 1;
                }
            }
        }
        let covered_share = covered as f64 / checked as f64;
        let on_ray_share = on_ray as f64 / checked as f64;
        assert!(
            covered_share < MOST_COVERED,
            "{position:?}: {covered} of {checked} covered"
        );
        assert!(
            on_ray_share > LEAST_ON_RAY,
            "{position:?}: {on_ray} of {checked} on the rays"
        );
    }
}

#[test]
fn the_sampled_rays_start_at_the_screen_leaving_the_eye_and_the_screen_clear() {
    let scene = Scene::default();
    let poses = [
        Camera::default(),
        Camera {
            position: vec3(0.5, 0.3, 1.0),
            yaw: 0.6,
            pitch: -0.15,
        },
    ];
    for camera in poses {
        let frame = frame_of(&scene, &camera);
        let (view, ..) = camera_axes(&camera);
        for direction in sampled_directions(&camera) {
            let unit = direction.normalize(); // the slide's D
            // The screen is d = 1 ahead of the eye along V: the ray meets it at t = d / D.V.
            let screen = 1.0 / unit.dot(view);
            let at = |t: f64| camera.position + unit * t;
            // The map shows the ray from above: a unit of t is this many map pixels along it.
            let map_pixels = unit.x.hypot(unit.z) * MAP_SCALE;
            let margin = 3.0 / map_pixels; // 3 map pixels
            // From past the eye's marker (3 map pixels) to 6 map pixels before the screen's row,
            // no sampled ray within a map pixel (the neighbouring rays start on the row, which
            // the edge rays cross at 45 degrees); 3 map pixels past it, the ray within a map pixel
            // (none of these rays hits anything that close to the screen).
            let mut t = margin;
            while t < screen - 2.0 * margin {
                let near = map_near(&frame, at(t), 1);
                assert!(
                    !near.contains(&RAY_COLOR),
                    "{camera:?}: a sampled ray at t = {t:.2}, before the screen at {screen:.2}"
                );
                assert!(
                    !near.contains(&MISS_COLOR),
                    "{camera:?}: a miss at t = {t:.2}, before the screen at {screen:.2}"
                );
                t += 0.25 / map_pixels; // a quarter map pixel
            }
            let past = map_near(&frame, at(screen + margin), 1);
            assert!(
                past.contains(&RAY_COLOR) || past.contains(&MISS_COLOR),
                "{camera:?}: no sampled ray past the screen"
            );
        }
        // The eye's marker and the screen's middle row, 1 ahead, in the camera's colour.
        let (_, right, _) = camera_axes(&camera);
        let middle_of_screen = camera.position + view;
        for point in [
            camera.position,
            middle_of_screen - right * 0.5,
            middle_of_screen + right * 0.5,
        ] {
            assert_eq!(
                map_near(&frame, point, 0),
                [CAMERA_COLOR],
                "{camera:?}: {point:?}"
            );
        }
    }
}

/// A 0RGB pixel as its red, green and blue bytes, each from 0 to 255.
fn channels(pixel: u32) -> [f64; 3] {
    [16, 8, 0].map(|shift| f64::from((pixel >> shift) & 255))
}

/// The RGB distance between two colours given as bytes.
fn rgb_distance(a: [f64; 3], b: [f64; 3]) -> f64 {
    let [dr, dg, db] = [0, 1, 2].map(|i| a[i] - b[i]);
    (dr * dr + dg * dg + db * db).sqrt()
}

/// How red-green colour-blind eyes see a colour: Machado, Oliveira and Fernandes (2009), severity
/// 1, applied to linear RGB (the sRGB curve undone, the matrix applied, the curve redone).
const PROTANOPIA: [[f64; 3]; 3] = [
    [0.152286, 1.052583, -0.204868],
    [0.114503, 0.786281, 0.099216],
    [-0.003882, -0.048116, 1.051998],
];
const DEUTERANOPIA: [[f64; 3]; 3] = [
    [0.367322, 0.860646, -0.227968],
    [0.280085, 0.672501, 0.047413],
    [-0.011820, 0.042940, 0.968881],
];

/// The sRGB transfer curve's parts (IEC 61966-2-1): linear below the knee, a power above it.
fn to_linear(level: f64) -> f64 {
    let c = level / 255.0;
    if c <= 0.04045 {
        c / 12.92
    } else {
        ((c + 0.055) / 1.055).powf(2.4)
    }
}

fn to_byte(linear: f64) -> f64 {
    let c = linear.clamp(0.0, 1.0);
    let encoded = if c <= 0.0031308 {
        12.92 * c
    } else {
        1.055 * c.powf(1.0 / 2.4) - 0.055
    };
    (encoded * 255.0).round()
}

fn simulate(pixel: u32, matrix: &[[f64; 3]; 3]) -> [f64; 3] {
    let linear = channels(pixel).map(to_linear);
    matrix.map(|row| to_byte(row[0] * linear[0] + row[1] * linear[1] + row[2] * linear[2]))
}

/// A colour as normal, protanopic and deuteranopic eyes see it.
fn as_seen(pixel: u32) -> [[f64; 3]; 3] {
    [
        channels(pixel),
        simulate(pixel, &PROTANOPIA),
        simulate(pixel, &DEUTERANOPIA),
    ]
}

/// The hue in degrees (0 red, 120 green, 240 blue) of a colour given as bytes.
fn hue(color: [f64; 3]) -> f64 {
    let [r, g, b] = color;
    // The angle of the colour around the grey axis, as the standard hexagon projection gives it.
    let x = r - (g + b) / 2.0;
    let y = (g - b) * 3f64.sqrt() / 2.0;
    y.atan2(x).to_degrees().rem_euclid(360.0)
}

/// Two colours closer than this in RGB, for any of the three eyes, are too alike to tell apart.
const LEAST_APART: f64 = 64.0;
/// A miss and a hit differ in hue by at least this many degrees, for each of the three eyes.
const LEAST_HUE_APART: f64 = 60.0;

/// The README's two pictures: the start pose, and the same pitched slightly down.
fn readme_poses() -> [Camera; 2] {
    let pitched = Camera {
        pitch: -0.15,
        ..Camera::default()
    };
    [Camera::default(), pitched]
}

#[test]
fn every_map_colour_is_told_apart_by_every_eye() {
    let scene = Scene::default();
    // The legend's colours: black, the eye and the screen (one colour), the sampled rays, their
    // misses, the light, shadow rays reaching it and blocked, mirror rays; then the balls' outlines.
    let named = [
        BACKGROUND,
        CAMERA_COLOR,
        RAY_COLOR,
        MISS_COLOR,
        LIGHT_COLOR,
        SHADOW_COLOR,
        BLOCKED_COLOR,
        MIRROR_COLOR,
    ];
    let outlines: Vec<u32> = scene
        .objects
        .iter()
        .filter_map(|(shape, material)| match shape {
            Shape::Sphere { .. } => Some(pixel_of(material.color)),
            Shape::Plane { .. } => None,
        })
        .collect();
    // Every one of them shows in one of the README's two pictures.
    let mut in_pictures: Vec<u32> = Vec::new();
    for camera in &readme_poses() {
        in_pictures.extend(map_of(&frame_of(&scene, camera)));
    }
    for color in named.iter().chain(&outlines) {
        assert!(
            in_pictures.contains(color),
            "{color:06x} is in neither picture"
        );
    }
    // Other level and slightly pitched poses of the demo: close to the balls, turned, far back.
    let more = [
        (vec3(0.0, 0.0, -1.5), 0.0, 0.0),
        (vec3(0.5, 0.5, 0.0), 0.0, -0.35),
        (vec3(-1.0, 0.0, 1.0), 0.4, 0.1),
        (vec3(1.5, -0.3, -1.0), -0.6, -0.2),
        (vec3(0.0, 0.0, 25.0), 0.0, 0.0),
    ];
    let mut seen = in_pictures;
    for (position, yaw, pitch) in more {
        let camera = Camera {
            position,
            yaw,
            pitch,
        };
        seen.extend(map_of(&frame_of(&scene, &camera)));
    }
    seen.sort_unstable();
    seen.dedup();
    // Every pair of colours, named or seen, far enough apart as each eye sees them; two balls'
    // outlines are told apart by where they are, not by colour.
    let others = seen
        .iter()
        .filter(|color| !named.contains(color) && !outlines.contains(color));
    let all: Vec<u32> = named
        .iter()
        .chain(&outlines)
        .chain(others)
        .copied()
        .collect();
    for (i, &a) in all.iter().enumerate() {
        for &b in &all[..i] {
            if outlines.contains(&a) && outlines.contains(&b) {
                continue;
            }
            for (eye, (seen_a, seen_b)) in ["normal", "protanopia", "deuteranopia"]
                .iter()
                .zip(as_seen(a).into_iter().zip(as_seen(b)))
            {
                let apart = rgb_distance(seen_a, seen_b);
                assert!(
                    apart >= LEAST_APART,
                    "{a:06x} and {b:06x}, {eye}: {apart:.0}"
                );
            }
        }
    }
    // A ray that misses differs from one that hits in hue, not only in brightness.
    for (hit, miss) in as_seen(RAY_COLOR).into_iter().zip(as_seen(MISS_COLOR)) {
        let turn = (hue(hit) - hue(miss)).abs();
        let apart = turn.min(360.0 - turn);
        assert!(
            apart >= LEAST_HUE_APART,
            "hues {hit:?} and {miss:?}: {apart:.0} degrees"
        );
    }
}

#[test]
fn off_the_map_the_eye_has_a_marker_on_the_edge_nearest_to_it() {
    let scene = scene_of(vec![], vec3(0.0, 5.0, -3.0));
    let last = (VIEW - 1) as f64;
    // The eye behind the map, beside it, and past its corner: the map pixel nearest to it, on the
    // edge, and the step from there into the map, in map pixels right and down.
    let cases = [
        (
            vec3(0.0, 0.0, 25.0),
            (0.0 - MAP_CORNER.x) * MAP_SCALE,
            last,
            (0.0, -1.0),
        ),
        (
            vec3(20.0, 0.0, -4.0),
            last,
            (-4.0 - MAP_CORNER.z) * MAP_SCALE,
            (-1.0, 0.0),
        ),
        (vec3(-30.0, 0.0, 40.0), 0.0, last, (1.0, -1.0)),
    ];
    for (position, column, row, (step_x, step_y)) in cases {
        let camera = Camera {
            position,
            ..Camera::default()
        };
        let frame = frame_of(&scene, &camera);
        let map_at = |steps: f64| {
            let x = column + step_x * steps;
            let y = row + step_y * steps;
            frame[y as usize * WIDTH + VIEW + x as usize]
        };
        // The marker is a square 7 map pixels wide centred on that pixel: it reaches 3 pixels into
        // the map from the edge, and not 4.
        for steps in [0.0, 3.0] {
            assert_eq!(map_at(steps), CAMERA_COLOR, "{position:?}: {steps} in");
        }
        assert_ne!(map_at(4.0), CAMERA_COLOR, "{position:?}: 4 in");
    }
    // On the map, no marker on the edges: the eye is where it is.
    let frame = frame_of(&scene, &Camera::default());
    let map = map_of(&frame);
    for i in 0..VIEW {
        let top = i;
        let bottom = (VIEW - 1) * VIEW + i;
        let left = i * VIEW;
        let right = left + VIEW - 1;
        for edge_pixel in [top, bottom, left, right] {
            assert_ne!(map[edge_pixel], CAMERA_COLOR, "map pixel {edge_pixel}");
        }
    }
}

#[test]
fn a_huge_spheres_outline_stays_within_a_pixel_of_its_circle() {
    // A sphere of radius 35 cut through its centre by the level slice, the eye looking away
    // from it so that no ray is drawn over its outline, and the light far off the map.
    let center = vec3(0.0, 0.0, -40.0);
    let radius = 35.0;
    let scene = scene_of(
        vec![sphere(center, radius, matte(PURE_RED))],
        vec3(0.0, 100.0, 100.0),
    );
    let camera = Camera {
        yaw: std::f64::consts::PI,
        ..Camera::default()
    };
    let frame = frame_of(&scene, &camera);
    // About every 0.011 units along the circle, of which 1,153 points are on the map.
    let points = 20_000;
    for i in 0..points {
        let angle = std::f64::consts::TAU * i as f64 / points as f64;
        let on_circle = center + vec3(angle.cos(), 0.0, angle.sin()) * radius;
        // 0.1 units (4 map pixels) inside the edges, so that all of map_near's pixels are on it.
        if inside_map(on_circle, 0.1) {
            assert!(
                map_near(&frame, on_circle, 1).contains(&pixel_of(PURE_RED)),
                "{on_circle:?}"
            );
        }
    }
}

#[test]
fn a_colour_brighter_than_white_is_clamped_to_255() {
    // A matte ball of colour (0, 0.3, 2) seen head on, lit from the eye: its blue, about 2 at the
    // centre, shows as 255; unclamped, about 510 would carry its ninth bit into green's byte.
    let center = vec3(0.0, 0.0, -4.0);
    let glowing = vec3(0.0, 0.3, 2.0);
    let camera = Camera::default();
    let scene = scene_of(vec![sphere(center, 1.0, matte(glowing))], camera.position);
    let frame = frame_of(&scene, &camera);
    let facing = center + vec3(0.0, 0.0, 1.0); // the point nearest the eye, N = L
    let [red, green, blue] = rgb(&frame, project(&camera, facing));
    let expected_green = byte(glowing.y * lit_share(facing, vec3(0.0, 0.0, 1.0), camera.position));
    assert_eq!(blue, 255);
    // Green exactly as the test's shading says: N.L at the pixel's centre is within 10^-4 of 1,
    // so 0.3 x 255 = 76.5 rounds down to 76 either way; even, so a carry from blue would show.
    assert_eq!(green, expected_green);
    assert_eq!(red, 0);
}
