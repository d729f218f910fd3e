//! Pixel tests of the headless `render`: each expectation is worked out here from the geometry,
//! with the test's own projection, not by calling the code under test.
#[allow(dead_code)]
#[path = "../src/main.rs"]
mod raytracer;

use raytracer::*;

const RED: Vec3 = vec3(0.9, 0.1, 0.1);
const SKY: Vec3 = vec3(0.4, 0.6, 1.0);
const WHITE: Vec3 = vec3(1.0, 1.0, 1.0);

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

fn floor() -> (Shape, Material) {
    let checkered = Material {
        color: WHITE,
        reflectivity: 0.0,
        checkered: true,
    };
    (
        Shape::Plane {
            normal: vec3(0.0, 1.0, 0.0),
            offset: 1.0,
        },
        checkered,
    )
}

fn scene(objects: Vec<(Shape, Material)>, light: Vec3) -> Scene {
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

fn brightness(frame: &[u32], at: (usize, usize)) -> u32 {
    rgb(frame, at).iter().sum()
}

fn byte(channel: f64) -> u32 {
    (channel * 255.0) as u32
}

fn cross(a: Vec3, b: Vec3) -> Vec3 {
    vec3(
        a.y * b.z - a.z * b.y,
        a.z * b.x - a.x * b.z,
        a.x * b.y - a.y * b.x,
    )
}

/// Where a world point shows in the 3D view: the camera looks along
/// (-sin yaw cos pitch, sin pitch, -cos yaw cos pitch) at a screen 1 away, 2 wide and 2 high.
fn project(camera: &Camera, point: Vec3) -> (usize, usize) {
    let (yaw, pitch) = (camera.yaw, camera.pitch);
    let forward = vec3(
        -yaw.sin() * pitch.cos(),
        pitch.sin(),
        -yaw.cos() * pitch.cos(),
    );
    let right = vec3(yaw.cos(), 0.0, -yaw.sin());
    let up = cross(right, forward);
    let d = point - camera.position;
    let (sx, sy) = (d.dot(right) / d.dot(forward), d.dot(up) / d.dot(forward));
    assert!(
        d.dot(forward) > 0.0 && sx.abs() < 1.0 && sy.abs() < 1.0,
        "{point:?} is off screen"
    );
    (((sx + 1.0) * 256.0) as usize, ((1.0 - sy) * 256.0) as usize)
}

/// Does the segment a-b pass through the sphere?
fn segment_hits_sphere(a: Vec3, b: Vec3, center: Vec3, radius: f64) -> bool {
    let ab = b - a;
    let t = ((center - a).dot(ab) / ab.dot(ab)).clamp(0.0, 1.0);
    let closest = a + ab * t - center;
    closest.dot(closest) < radius * radius
}

fn odd_square(point: Vec3) -> bool {
    (point.x.floor() + point.z.floor()).rem_euclid(2.0) == 1.0
}

#[test]
fn sky_pixels_are_the_sky_colour() {
    let scene = scene(
        vec![sphere(vec3(0.0, 0.0, -4.0), 1.0, matte(RED))],
        vec3(0.0, 5.0, 0.0),
    );
    let frame = frame_of(&scene, &Camera::default());
    let sky = [byte(SKY.x), byte(SKY.y), byte(SKY.z)];
    for corner in [(0, 0), (511, 0), (0, 511), (511, 511), (256, 20)] {
        assert_eq!(rgb(&frame, corner), sky, "pixel {corner:?}");
    }
}

#[test]
fn a_sphere_covers_its_projected_centre_and_not_past_its_silhouette() {
    let (center, radius) = (vec3(1.0, 0.5, -5.0), 1.0);
    let scene = scene(
        vec![sphere(center, radius, matte(RED))],
        vec3(0.0, 0.0, 0.0),
    );
    let camera = Camera::default();
    let frame = frame_of(&scene, &camera);
    let [r, g, b] = rgb(&frame, project(&camera, center));
    assert!(r > 2 * g && r > 2 * b, "centre is {:?}, not red", [r, g, b]);
    // The silhouette seen from the eye is a cone of half-angle asin(r / distance): step just past it.
    let distance = center.length();
    let half_angle = (radius / distance).asin() + 0.02;
    let toward = center.normalize();
    let beside = vec3(toward.z, 0.0, -toward.x); // horizontal, at right angles to `toward`
    let outside = (toward * half_angle.cos() + beside * half_angle.sin()) * distance;
    let sky = [byte(SKY.x), byte(SKY.y), byte(SKY.z)];
    assert_eq!(rgb(&frame, project(&camera, outside)), sky);
}

#[test]
fn the_side_facing_the_light_is_brighter() {
    let center = vec3(0.0, 0.0, -4.0);
    let scene = scene(
        vec![sphere(center, 1.0, matte(RED))],
        vec3(-10.0, 0.0, -4.0),
    );
    let camera = Camera::default();
    let frame = frame_of(&scene, &camera);
    let lit = project(&camera, center + vec3(-0.7, 0.0, 0.7));
    let dark = project(&camera, center + vec3(0.7, 0.0, 0.7));
    assert!(brightness(&frame, lit) > 3 * brightness(&frame, dark));
}

#[test]
fn a_sphere_between_floor_and_light_casts_a_shadow() {
    let (center, light) = (vec3(0.0, 0.0, -5.0), vec3(0.0, 3.0, -5.0));
    let scene = scene(vec![floor(), sphere(center, 1.0, matte(RED))], light);
    let camera = Camera {
        position: vec3(0.0, 1.0, 0.0),
        pitch: -0.3,
        yaw: 0.0,
    };
    let frame = frame_of(&scene, &camera);
    // Two floor points of the same parity, both in view past the sphere, one hidden from the light.
    let (shaded, lit) = (vec3(0.5, -1.0, -4.2), vec3(2.5, -1.0, -4.2));
    assert!(segment_hits_sphere(shaded, light, center, 1.0));
    assert!(!segment_hits_sphere(lit, light, center, 1.0));
    for point in [shaded, lit] {
        assert!(!segment_hits_sphere(camera.position, point, center, 1.0));
    }
    assert_eq!(odd_square(shaded), odd_square(lit));
    let (shaded, lit) = (project(&camera, shaded), project(&camera, lit));
    assert!(brightness(&frame, shaded) * 2 < brightness(&frame, lit));
}

#[test]
fn only_occluders_between_the_point_and_the_light_cast_shadows() {
    // A ball above the light, and one beside it: neither lies between the floor and the light.
    let light = vec3(0.0, 2.0, -4.0);
    let above = sphere(vec3(0.0, 4.0, -4.0), 1.0, matte(RED));
    let beside = sphere(vec3(4.0, 0.0, -8.0), 1.0, matte(RED));
    let camera = Camera {
        position: vec3(0.0, 1.0, 0.0),
        pitch: -0.3,
        yaw: 0.0,
    };
    let lit = frame_of(&scene(vec![floor()], light), &camera);
    let with_balls = frame_of(&scene(vec![floor(), above, beside], light), &camera);
    let point = project(&camera, vec3(0.5, -1.0, -3.5));
    assert_eq!(rgb(&with_balls, point), rgb(&lit, point));
}

#[test]
fn the_floor_is_checkered_by_floor_x_plus_floor_z() {
    let scene = scene(vec![floor()], vec3(0.0, 100.0, 0.0));
    let camera = Camera {
        position: vec3(0.0, 1.0, 3.0),
        pitch: -0.5,
        yaw: 0.0,
    };
    let frame = frame_of(&scene, &camera);
    // Square centres on both sides of x = 0 and of z = 0.
    for x in [-1.5, -0.5, 0.5, 1.5] {
        for z in [-1.5, -0.5, 0.5, 1.5] {
            let point = vec3(x, -1.0, z);
            let green = rgb(&frame, project(&camera, point))[1];
            assert_eq!(
                green < 128,
                odd_square(point),
                "square at {point:?} is {green}"
            );
        }
    }
}

/// Where the mirror sphere's pixel (x, y) sends its reflected ray, by the test's own geometry.
fn reflected_ray(camera: &Camera, center: Vec3, (x, y): (usize, usize)) -> Option<(Vec3, Vec3)> {
    let (u, v) = (
        (x as f64 + 0.5) / 256.0 - 1.0,
        1.0 - (y as f64 + 0.5) / 256.0,
    );
    let d = vec3(u, v, -1.0).normalize(); // the default camera
    let oc = camera.position - center;
    let (b, c) = (oc.dot(d), oc.dot(oc) - 1.0);
    let t = -b - (b * b - c).sqrt();
    let point = camera.position + d * t;
    let n = point - center;
    (t > 0.0).then(|| (point, d - n * (2.0 * d.dot(n))))
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
    let scene = scene(vec![floor(), sphere(center, 1.0, mirror)], light);
    let camera = Camera::default();
    let frame = frame_of(&scene, &camera);
    let sky = [byte(SKY.x), byte(SKY.y), byte(SKY.z)];
    let (mut bright, mut dark, mut skies) = (0, 0, 0);
    for y in (128..384).step_by(4) {
        for x in (192..320).step_by(4) {
            let Some((point, direction)) = reflected_ray(&camera, center, (x, y)) else {
                continue;
            };
            if direction.y >= 0.0 {
                assert_eq!(rgb(&frame, (x, y)), sky, "pixel {x}, {y} reflects the sky");
                skies += 1;
                continue;
            }
            let on_floor = point + direction * ((-1.0 - point.y) / direction.y);
            let near_edge = |w: f64| (w - w.round()).abs() < 0.05;
            if near_edge(on_floor.x) || near_edge(on_floor.z) {
                continue;
            }
            if segment_hits_sphere(on_floor, light, center, 1.0) || on_floor.length() > 20.0 {
                continue;
            }
            let green = rgb(&frame, (x, y))[1];
            assert_eq!(green < 100, odd_square(on_floor), "pixel {x}, {y}: {green}");
            if odd_square(on_floor) {
                dark += 1
            } else {
                bright += 1
            }
        }
    }
    assert!(
        bright > 5 && dark > 5 && skies > 5,
        "{bright} {dark} {skies}"
    );
}

#[test]
fn turning_and_moving_the_camera_move_the_image() {
    let ball = vec3(-3.0, 0.0, -1.5);
    let scene = scene(vec![sphere(ball, 0.5, matte(RED))], vec3(0.0, 5.0, 0.0));
    let is_red = |frame: &[u32], at| {
        let [r, g, b] = rgb(frame, at);
        r > 2 * g && r > 2 * b
    };
    // Straight ahead is -z; the ball is far to the left, out of view: after a quarter turn left
    // the view looks down -x, the ball is 3 ahead and 1.5 right: half way to the right edge.
    let turned = Camera {
        yaw: std::f64::consts::FRAC_PI_2,
        ..Camera::default()
    };
    assert_eq!(project(&turned, ball), (384, 256));
    let frame = frame_of(&scene, &turned);
    assert!(is_red(&frame, (384, 256)));
    assert!(!is_red(&frame_of(&scene, &Camera::default()), (384, 256)));
    // Stepping 1.5 along +z puts the ball dead ahead of the turned camera.
    let moved = Camera {
        position: vec3(0.0, 0.0, -1.5),
        ..turned
    };
    let frame = frame_of(&scene, &moved);
    assert!(is_red(&frame, (256, 256)) && !is_red(&frame, (384, 256)));
}

/// The 2D map: x to the right from MAP_CORNER.x, z down from MAP_CORNER.z, MAP_SCALE pixels a unit.
fn map_pixel(frame: &[u32], x: f64, z: f64) -> u32 {
    let column = ((x - MAP_CORNER.x) * MAP_SCALE) as usize;
    let row = ((z - MAP_CORNER.z) * MAP_SCALE) as usize;
    frame[row * WIDTH + VIEW + column]
}

#[test]
fn the_slice_shows_the_camera_a_sphere_outline_and_a_sampled_ray() {
    let center = vec3(2.0, 0.0, -5.0);
    let pure_red = Material {
        color: vec3(1.0, 0.0, 0.0),
        ..matte(RED)
    };
    let scene = scene(vec![sphere(center, 1.0, pure_red)], vec3(0.0, 5.0, 2.0));
    let frame = frame_of(&scene, &Camera::default());
    assert_eq!(map_pixel(&frame, 0.0, 0.0), 0xffffff, "the camera dot");
    // The far side of the outline, hidden from the rays by the sphere itself.
    for angle in [1.2f64, 1.6, 2.0] {
        let (x, z) = (center.x + angle.cos(), center.z - angle.sin());
        let near = [-0.02, 0.0, 0.02].map(|dz| map_pixel(&frame, x, z + dz));
        assert!(near.contains(&0xff0000), "outline at {x}, {z}: {near:x?}");
    }
    // The middle row's first ray leaves along about (-1, 0, -1) and hits nothing.
    let background = map_pixel(&frame, -4.0, -3.0);
    for t in [2.0, 4.0, 6.0] {
        let on_ray = (-1..=1).any(|dz| map_pixel(&frame, -t, -t + dz as f64 * 0.03) != background);
        assert!(on_ray, "ray missing at {t}");
    }
    assert_ne!(map_pixel(&frame, -3.0, -3.0), background);
    assert_eq!(
        map_pixel(&frame, -3.4, -3.0),
        background,
        "just left of the ray"
    );
}

#[test]
fn the_frame_on_all_cores_equals_tracing_each_pixel_on_one() {
    let (scene, camera) = (Scene::default(), Camera::default());
    let frame = frame_of(&scene, &camera);
    let screen = camera.screen();
    let center = |i: usize| (i as f64 + 0.5) / VIEW as f64;
    for y in 0..VIEW {
        for x in 0..VIEW {
            let ray = camera.primary_ray(screen, center(x), center(y));
            let alone = to_rgb(scene.trace(&ray, &scene.objects, 0));
            assert_eq!(frame[y * WIDTH + x], alone, "pixel {x}, {y}");
        }
    }
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
    // Rays through the screen's middle row of a level camera are horizontal: they never meet a
    // floor below (or above) the eye, so a floor changes nothing on the map.
    for (position, yaw) in [
        (vec3(0.0, 0.0, 0.0), 0.0),
        (vec3(0.7, 0.3, -1.0), 0.4),
        (vec3(-1.0, 2.5, 1.0), -2.0),
        (vec3(0.0, -3.0, 0.0), 1.0),
    ] {
        let camera = Camera {
            position,
            yaw,
            pitch: 0.0,
        };
        let light = vec3(0.0, 5.0, 0.0);
        let empty = frame_of(&scene(vec![], light), &camera);
        let floor_only = frame_of(&scene(vec![floor()], light), &camera);
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
    let scene = scene(
        vec![floor(), sphere(center, 1.0, matte(RED))],
        vec3(0.0, 5.0, 2.0),
    );
    let frame = frame_of(&scene, &Camera::default());
    let cut = 0.75f64.sqrt();
    let mut marked = 0;
    for x in (0..VIEW).step_by(10) {
        // The sampled ray of column x, in the plane y = 0, meets the circle where |O + tD - C| = cut.
        let d = vec3((x as f64 + 0.5) / 256.0 - 1.0, 0.0, -1.0).normalize();
        let to_center = vec3(center.x, 0.0, center.z);
        let t_center = to_center.dot(d);
        let p2 = to_center.dot(to_center) - t_center * t_center;
        if p2 >= cut * cut - 1e-3 {
            continue; // misses, or only grazes, the circle
        }
        let hit = d * (t_center - (cut * cut - p2).sqrt());
        let around = [-0.025, 0.0, 0.025];
        let dot = around.iter().any(|&dx| {
            (around.iter()).any(|&dz| map_pixel(&frame, hit.x + dx, hit.z + dz) == 0xff4040)
        });
        assert!(dot, "no hit marked at {hit:?} for column {x}");
        marked += 1;
    }
    assert!(marked >= 5, "{marked} sampled rays hit the sphere");
}

#[test]
fn odd_cameras_render_valid_frames() {
    let scene = Scene::default();
    let inside = Camera {
        position: vec3(0.3, 0.0, -4.5),
        ..Camera::default()
    };
    let frame = frame_of(&scene, &inside);
    assert!(frame.iter().all(|pixel| pixel >> 24 == 0));
    // From the centre of the mirror ball every ray meets its inside, never the sky.
    let sky = [byte(scene.sky.x), byte(scene.sky.y), byte(scene.sky.z)];
    assert!((0..VIEW).all(|y| (0..VIEW).all(|x| rgb(&frame, (x, y)) != sky)));
    // Below the floor, looking up at it: its underside faces away from the light, so it is dark.
    let below = Camera {
        position: vec3(0.0, -3.0, 0.0),
        pitch: 1.0,
        yaw: 0.0,
    };
    let frame = frame_of(&scene, &below);
    assert!(frame.iter().all(|pixel| pixel >> 24 == 0));
    let underside = project(&below, vec3(0.5, -1.0, -1.5));
    assert!(
        rgb(&frame, underside)[1] <= byte(AMBIENT * 0.9) + 1,
        "{:?}",
        rgb(&frame, underside)
    );
    let down = Camera {
        pitch: -std::f64::consts::FRAC_PI_2,
        ..Camera::default()
    };
    let frame = frame_of(&scene, &down);
    assert!(frame.iter().all(|pixel| pixel >> 24 == 0));
    // Straight down from y = 0 the middle of the view is the floor at (0, -1, 0): square 0 + 0, even.
    assert!(rgb(&frame, (256, 256))[1] > 128);
}
