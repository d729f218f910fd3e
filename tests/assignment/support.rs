// What the steps' tests share: scenes, a frame and its pixels, where a world point shows in the 3D
// view and on the map. The tests work out what they expect with glam's vector maths, not with
// main.rs's `Vec3`: a slip there fails the tests, rather than moving what they expect too.
use glam::{DMat3, DVec3, dvec3};

/// A test's point handed to main.rs, and main.rs's read back, field by field.
fn to_vec3(v: DVec3) -> Vec3 {
    vec3(v.x, v.y, v.z)
}

fn to_dvec3(v: Vec3) -> DVec3 {
    dvec3(v.x, v.y, v.z)
}

// The README's figures, which the tests hold main.rs to: if you change one in main.rs on purpose,
// change it here too.
const README_AMBIENT: f64 = 0.1;
const README_ODD_SQUARE_BRIGHTNESS: f64 = 0.25;
const README_MAX_DEPTH: u32 = 5; // mirror bounces
const README_SCREEN_DISTANCE: f64 = 1.0; // the screen 1 ahead of the eye, 2 wide and 2 high
const README_SAMPLED_EVERY: usize = 10;
const README_MARKER_RADIUS: usize = 3; // markers 7 map pixels wide
const README_MAP_CORNER: DVec3 = dvec3(-6.4, 0.0, -9.4); // the map's top left x and z
const README_MAP_SIDE: f64 = 12.8; // the map's width and height, in world units
const README_MOVE_SPEED: f64 = 2.0; // units a second
const README_TURN_SPEED: f64 = 1.5; // radians a second

/// Half the 3D view's width and height, in pixels: its middle, from its top left.
const HALF: f64 = VIEW as f64 / 2.0;

const RED: DVec3 = dvec3(1.0, 0.0, 0.0);
const RED_ON_THE_MAP: u32 = 0xff0000; // RED as the window shows it
const WHITE: DVec3 = DVec3::ONE;
const ORIGIN: DVec3 = DVec3::ZERO;
const UP: DVec3 = DVec3::Y;
const RIGHT: DVec3 = DVec3::X;
const AHEAD: DVec3 = dvec3(0.0, 0.0, -1.0); // where the default camera looks

/// One of a scene's objects: a primitive and its material.
type Object = (Primitive, Material);

/// A primitive of a colour, of a reflectivity from 0 (matte) to 1 (a perfect mirror), checkered
/// or not. Any field you add to Material comes from the demo's floor.
fn object(primitive: Primitive, color: DVec3, reflectivity: f64, checkered: bool) -> Object {
    let color = to_vec3(color);
    (primitive, Material { color, reflectivity, checkered, ..Scene::demo().objects[0].1 })
}

fn ball(center: DVec3, radius: f64, color: DVec3, reflectivity: f64) -> Object {
    let center = to_vec3(center);
    object(Primitive::Sphere { center, radius }, color, reflectivity, false)
}

/// The plane p.N + d = 0 with N = (0, 1, 0) and d = 1: y = -1, the floor.
fn floor_plane() -> Primitive {
    let normal = vec3(0.0, 1.0, 0.0);
    Primitive::Plane { normal, offset: 1.0 }
}

fn checkered_floor() -> Object {
    object(floor_plane(), WHITE, 0.0, true)
}

fn scene(objects: Vec<Object>, light: DVec3) -> Scene {
    Scene { objects, light: to_vec3(light), ..Scene::demo() }
}

/// The eye at `position`, turned `yaw` radians left and tilted `pitch` up.
fn camera_at(position: DVec3, yaw: f64, pitch: f64) -> Camera {
    Camera { position: to_vec3(position), yaw, pitch, ..Camera::default() }
}

/// The frame `render` draws, in a buffer that held another frame (white), as a window's does. One
/// not done in 5 s (it takes a tenth of one) fails the test, rather than hang it.
fn rendered(objects: Vec<Object>, light: DVec3, camera: Camera) -> Vec<u32> {
    let world = scene(objects, light);
    let (sender, receiver) = std::sync::mpsc::channel();
    std::thread::spawn(move || {
        let mut pixels = vec![0xffffff; WIDTH * VIEW];
        render(&world, &camera, &mut pixels);
        sender.send(pixels)
    });
    let five_seconds = std::time::Duration::from_secs(5);
    receiver.recv_timeout(five_seconds).expect("render panicked (its message is above) or has not finished a frame in 5 s: then look in src/main.rs for a loop that never ends (draw_ray's count of dots, after a slip in the vector maths)")
}

/// The colour a ray from `from` towards `to` brings back: what a pixel whose ray it is shows. Its
/// shadow ray leaves a little off the surface, so N.L may be a ten-thousandth off.
fn traced(objects: Vec<Object>, light: DVec3, from: DVec3, to: DVec3) -> DVec3 {
    let ray = Ray::new(to_vec3(from), to_vec3(to - from), f64::INFINITY);
    to_dvec3(scene(objects, light).trace(ray, 0))
}

/// The colour the 3D view's pixel (x, y) shows, from 0 to 1: its red, green and blue bytes / 255.
fn rgb(frame: &[u32], (x, y): (usize, usize)) -> DVec3 {
    let [_, bytes @ ..] = frame[y * WIDTH + x].to_be_bytes(); // 0, red, green, blue
    DVec3::from_array(bytes.map(f64::from)) / 255.0
}

/// Red, as a red ball shows however it is lit: more red than green or blue.
fn is_red(color: DVec3) -> bool {
    color.x > color.y.max(color.z)
}

/// The camera matrix: turned `yaw` about y, after tilted `pitch` about x. It turns -z, x and y into
/// the camera's view, right and up.
fn camera_matrix(camera: Camera) -> DMat3 {
    DMat3::from_rotation_y(camera.yaw) * DMat3::from_rotation_x(camera.pitch)
}

/// The direction through the point (x, y) of the 3D view, in pixels from its top left: p(u, v) - E
/// on the slide's screen, d ahead, from -1 to 1 across and up.
fn through(camera: Camera, x: f64, y: f64) -> DVec3 {
    camera_matrix(camera) * dvec3(x / HALF - 1.0, 1.0 - y / HALF, -README_SCREEN_DISTANCE)
}

/// The 3D view's pixel that shows a world point in view: the point in the camera's own x, y and -z
/// (ahead), its x and y over how far ahead it is, from -1 to 1 on the screen.
fn pixel_of(camera: Camera, point: DVec3) -> (usize, usize) {
    let seen = camera_matrix(camera).transpose() * (point - to_dvec3(camera.position));
    let screen = seen * (README_SCREEN_DISTANCE / -seen.z);
    (((1.0 + screen.x) * HALF) as usize, ((1.0 - screen.y) * HALF) as usize)
}

/// The unit directions of the rays the map shows: through every 10th column's centre, on the line
/// between the screen's two middle rows.
fn sampled(camera: Camera) -> Vec<DVec3> {
    let columns = (0..VIEW).step_by(README_SAMPLED_EVERY);
    columns.map(|x| through(camera, x as f64 + 0.5, HALF).normalize()).collect()
}

/// The map's colours up to `reach` pixels either side of the pixel over a world point, at least
/// that far inside the map: x to the right and z down from its top left corner.
fn map_near(frame: &[u32], point: DVec3, reach: usize) -> Vec<u32> {
    let middle = (point - README_MAP_CORNER) * (VIEW as f64 / README_MAP_SIDE);
    let (x, z) = (middle.x as usize, middle.z as usize);
    let row = |z| (x - reach..=x + reach).map(move |x| frame[z * WIDTH + VIEW + x]);
    (z - reach..=z + reach).flat_map(row).collect()
}

/// Is `color` drawn on the map within a pixel of a world point?
fn drawn_near(frame: &[u32], point: DVec3, color: u32) -> bool {
    map_near(frame, point, 1).contains(&color)
}
