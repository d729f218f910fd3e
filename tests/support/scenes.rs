//! The tests' own scenes and geometry. Each expectation is worked out here from the slides'
//! formulas (the camera's screen, the ray-sphere quadratic, N.L) with the tests' own vector maths,
//! `V3`, and none of main.rs's: a slip there (in dot, length, +, -, *) then fails the tests of the
//! steps it breaks instead of moving their expectations too. Here too: how the tests print points
//! and poses, and a frame that never ends failing as a sentence.
use crate::*;
use std::fmt;
use std::io::Write;
use std::ops::{Add, Mul, Sub};
use std::sync::mpsc;
use std::time::Duration;

/// The tests' own 3D vector: a point, a direction or a colour (x, y, z = red, green, blue).
#[derive(Clone, Copy, Default, PartialEq)]
pub struct V3 {
    pub x: f64,
    pub y: f64,
    pub z: f64,
}

pub const fn v3(x: f64, y: f64, z: f64) -> V3 {
    V3 { x, y, z }
}

impl V3 {
    pub fn dot(self, other: V3) -> f64 {
        self.x * other.x + self.y * other.y + self.z * other.z
    }
    pub fn length(self) -> f64 {
        self.dot(self).sqrt()
    }
    pub fn normalize(self) -> V3 {
        self * (1.0 / self.length())
    }
    pub fn cross(self, other: V3) -> V3 {
        v3(
            self.y * other.z - self.z * other.y,
            self.z * other.x - self.x * other.z,
            self.x * other.y - self.y * other.x,
        )
    }
}

impl Add for V3 {
    type Output = V3;
    fn add(self, other: V3) -> V3 {
        v3(self.x + other.x, self.y + other.y, self.z + other.z)
    }
}

impl Sub for V3 {
    type Output = V3;
    fn sub(self, other: V3) -> V3 {
        v3(self.x - other.x, self.y - other.y, self.z - other.z)
    }
}

impl Mul<f64> for V3 {
    type Output = V3;
    fn mul(self, scale: f64) -> V3 {
        v3(self.x * scale, self.y * scale, self.z * scale)
    }
}

/// A test's point handed to the program, and the program's read back: field by field.
impl From<V3> for Vec3 {
    fn from(V3 { x, y, z }: V3) -> Vec3 {
        Vec3 { x, y, z }
    }
}

impl From<Vec3> for V3 {
    fn from(Vec3 { x, y, z }: Vec3) -> V3 {
        V3 { x, y, z }
    }
}

impl fmt::Debug for V3 {
    fn fmt(&self, f: &mut fmt::Formatter) -> fmt::Result {
        write!(f, "({:.2}, {:.2}, {:.2})", self.x, self.y, self.z)
    }
}

impl fmt::Debug for Vec3 {
    fn fmt(&self, f: &mut fmt::Formatter) -> fmt::Result {
        V3::from(*self).fmt(f)
    }
}

impl fmt::Debug for Camera {
    fn fmt(&self, f: &mut fmt::Formatter) -> fmt::Result {
        let Camera {
            position,
            yaw,
            pitch,
        } = self;
        write!(
            f,
            "the eye at {position:?} turned {yaw:.2} and tilted {pitch:.2} radians"
        )
    }
}

/// The figures the README gives, which the tests hold the program to. A test that holds one
/// names it when it fails: if you changed that figure in src/main.rs on purpose, change it here
/// too, and the tests follow it.
pub const README_AMBIENT: f64 = 0.1; // the share of the light a surface gets even in shadow
pub const README_ODD_SQUARE: f64 = 0.25; // the floor's odd squares show a quarter of that light
pub const README_SQUARE_SIZE: f64 = 1.0; // the floor's squares are 1 unit wide
pub const README_BOUNCES: u32 = 5; // mirror bounces a ray is followed through at most
pub const README_SCREEN_DISTANCE: f64 = 1.0; // the screen is 1 ahead of the eye, 2 wide and 2 high
pub const README_SAMPLED_EVERY: usize = 10; // the map shows every 10th ray of the screen's middle row
pub const README_MARKER_REACH: i32 = 3; // the light's and the eye's markers: 3 map pixels either side
pub const README_MOVE_SPEED: f64 = 2.0; // units a second along each held key's direction
pub const README_TURN_SPEED: f64 = 1.5; // radians a second

/// The figures as the README gives them, with their names here, for `holds`.
pub const AMBIENT_FIGURE: &str = "ambient 0.1 (README_AMBIENT)";
pub const ODD_SQUARE_FIGURE: &str = "odd squares a quarter as bright (README_ODD_SQUARE)";
pub const SQUARE_FIGURE: &str = "unit squares (README_SQUARE_SIZE)";
pub const BOUNCES_FIGURE: &str = "5 bounces (README_BOUNCES)";
pub const SCREEN_FIGURE: &str = "screen 1 ahead and 2 wide (README_SCREEN_DISTANCE)";
pub const SAMPLED_FIGURE: &str = "every 10th ray (README_SAMPLED_EVERY)";
pub const MARKER_FIGURE: &str = "markers 7 pixels wide (README_MARKER_REACH)";
pub const SPEED_FIGURE: &str =
    "2 units and 1.5 radians a second (README_MOVE_SPEED, README_TURN_SPEED)";

/// What a failing test adds about the README figures it holds the program to.
pub fn holds(figures: &[&str]) -> String {
    let (last, others) = figures.split_last().expect("a figure");
    let listed = match others {
        [] => last.to_string(),
        _ => format!("{} and {last}", others.join(", ")),
    };
    format!(
        "This test holds src/main.rs to the README's {listed}: if you changed one on purpose, \
         change it in tests/support/scenes.rs too. If not, the tracer is wrong here; if many \
         tests fail at once, look first at what they share, main.rs's vector maths (Vec3)."
    )
}

pub const SKY: V3 = v3(0.4, 0.6, 1.0);
pub const WHITE: V3 = v3(1.0, 1.0, 1.0);
pub const RED: V3 = v3(0.9, 0.1, 0.1);
pub const PURE_RED: V3 = v3(1.0, 0.0, 0.0); // its outline on the map is exactly 0xff0000
pub const PURE_GREEN: V3 = v3(0.0, 1.0, 0.0);
pub const PURE_BLUE: V3 = v3(0.0, 0.0, 1.0);
pub const FLOOR_Y: f64 = -1.0;
pub const HALF_VIEW: f64 = VIEW as f64 / 2.0; // the screen's middle, in pixels from an edge

pub fn matte(color: V3) -> Material {
    mirror(color, 0.0)
}

/// A surface that reflects `reflectivity` of what its mirror ray brings back.
pub fn mirror(color: V3, reflectivity: f64) -> Material {
    Material {
        color: color.into(),
        reflectivity,
        checkered: false,
    }
}

pub fn sphere(center: V3, radius: f64, material: Material) -> (Primitive, Material) {
    let center = center.into();
    (Primitive::Sphere { center, radius }, material)
}

/// A white checkered floor y = FLOOR_Y: the plane p.N + d = 0 with N = (0, 1, 0), d = -FLOOR_Y.
pub fn checkered_floor() -> (Primitive, Material) {
    let floor = Primitive::Plane {
        normal: v3(0.0, 1.0, 0.0).into(),
        offset: -FLOOR_Y,
    };
    let checkered = Material {
        checkered: true,
        ..matte(WHITE)
    };
    (floor, checkered)
}

pub fn scene_of(objects: Vec<(Primitive, Material)>, light: V3) -> Scene {
    Scene {
        objects,
        light: light.into(),
        sky: SKY.into(),
    }
}

/// A camera at `position` turned `yaw` radians left and tilted `pitch` radians up.
pub fn camera_at(position: V3, yaw: f64, pitch: f64) -> Camera {
    Camera {
        position: position.into(),
        yaw,
        pitch,
    }
}

/// The eye's position, in the tests' own maths.
pub fn eye(camera: &Camera) -> V3 {
    camera.position.into()
}

/// The program's ray from `origin` along `direction`, as far as `t`.
pub fn ray_from(origin: V3, direction: V3, t: f64) -> Ray {
    Ray::new(origin.into(), direction.into(), t)
}

/// A frame takes tens of milliseconds; one that takes this long will not end.
const FRAME_LIMIT: Duration = Duration::from_secs(5);

/// The frame `render` draws of `scene` from `camera`. If it has not finished after FRAME_LIMIT,
/// the test program stops with a sentence saying so, rather than running for ever.
pub fn frame_of(scene: &Scene, camera: &Camera) -> Vec<u32> {
    let (finished, watched) = mpsc::channel::<()>();
    let pose = format!("{camera:?}");
    std::thread::spawn(move || {
        if watched.recv_timeout(FRAME_LIMIT) == Err(mpsc::RecvTimeoutError::Timeout) {
            let _ = writeln!(
                std::io::stderr(),
                "A frame from {pose} did not finish in {} s (it takes well under a second): \
                 render never ends. Look in src/main.rs for a slip in the vector maths (dot, \
                 length, normalize, +, -, *), which can make draw_ray's count of dots endless, \
                 or for a loop that never stops.",
                FRAME_LIMIT.as_secs()
            );
            std::process::exit(1);
        }
    });
    let mut frame = vec![0; WIDTH * VIEW];
    render(scene, camera, &mut frame);
    drop(finished); // the watcher wakes and ends
    frame
}

/// The 3D view's pixel (x, y) as [red, green, blue] bytes.
pub fn rgb(frame: &[u32], (x, y): (usize, usize)) -> [u32; 3] {
    let pixel = frame[y * WIDTH + x];
    [pixel >> 16 & 255, pixel >> 8 & 255, pixel & 255]
}

/// A colour channel from 0 to 1 as a byte from 0 to 255, as the window shows it.
pub fn byte(channel: f64) -> u32 {
    (channel * 255.0) as u32
}

pub fn bytes(color: V3) -> [u32; 3] {
    [byte(color.x), byte(color.y), byte(color.z)]
}

/// A colour as a 0RGB pixel, as the map draws a ball's outline.
pub fn pixel_of(color: V3) -> u32 {
    let [red, green, blue] = bytes(color);
    red << 16 | green << 8 | blue
}

/// The README's shading: ambient + (1 - ambient) N.L, where N.L <= 0 (the light behind the
/// surface) adds nothing.
pub fn lit_share(point: V3, normal: V3, light: V3) -> f64 {
    let n_dot_l = normal.dot((light - point).normalize());
    README_AMBIENT + (1.0 - README_AMBIENT) * n_dot_l.max(0.0)
}

/// The camera's view, right and up directions: it looks along
/// (-sin yaw cos pitch, sin pitch, -cos yaw cos pitch), right is level, up is right x view.
pub fn camera_axes(camera: &Camera) -> (V3, V3, V3) {
    let Camera { yaw, pitch, .. } = *camera;
    let view = v3(
        -yaw.sin() * pitch.cos(),
        pitch.sin(),
        -yaw.cos() * pitch.cos(),
    );
    let right = v3(yaw.cos(), 0.0, -yaw.sin());
    (view, right, right.cross(view))
}

/// The 3D view's pixel that shows a world point: the slide's screen, d ahead, 2 wide and 2 high.
pub fn project(camera: &Camera, point: V3) -> (usize, usize) {
    let (view, right, up) = camera_axes(camera);
    let d = point - eye(camera);
    let ahead = d.dot(view) / README_SCREEN_DISTANCE;
    let across = d.dot(right) / ahead; // from -1 at the left edge to 1 at the right
    let upward = d.dot(up) / ahead; // from -1 at the bottom to 1 at the top
    assert!(
        ahead > 0.0 && across.abs() < 1.0 && upward.abs() < 1.0,
        "the test is wrong, not the program: {point:?} is off the screen"
    );
    let column = (across + 1.0) * HALF_VIEW;
    let row = (1.0 - upward) * HALF_VIEW;
    (column as usize, row as usize)
}

/// Where a ray O + tD from outside a sphere first meets it, by the quadratic |O + tD - C|² = r²:
/// the near root, if it is in front. D is unit, so the quadratic's a is 1, and with b halved its
/// roots are t = -b/2 ± √((b/2)² - c).
pub fn ray_sphere(origin: V3, direction: V3, center: V3, radius: f64) -> Option<V3> {
    let d = direction.normalize();
    let oc = origin - center;
    let half_b = oc.dot(d);
    let discriminant = half_b * half_b - (oc.dot(oc) - radius * radius);
    if discriminant < 0.0 {
        return None; // the line passes the sphere by
    }
    let t = -half_b - discriminant.sqrt();
    (t > 0.0).then(|| origin + d * t)
}

/// The ray through the centre of the 3D view's pixel (x, y): D = p(u, v) - E on the slide's screen.
pub fn pixel_direction(camera: &Camera, (x, y): (usize, usize)) -> V3 {
    let (view, right, up) = camera_axes(camera);
    let across = (x as f64 + 0.5) / HALF_VIEW - 1.0;
    let upward = 1.0 - (y as f64 + 0.5) / HALF_VIEW;
    view * README_SCREEN_DISTANCE + right * across + up * upward
}

/// Where the ray through the 3D view's pixel (x, y) meets the floor: t = (FLOOR_Y - E.y) / D.y.
pub fn floor_seen(camera: &Camera, pixel: (usize, usize)) -> V3 {
    let d = pixel_direction(camera, pixel);
    eye(camera) + d * ((FLOOR_Y - camera.position.y) / d.y)
}

/// The map's sampled rays: through every 10th column's centre on the screen's middle row.
pub fn sampled_directions(camera: &Camera) -> Vec<V3> {
    let (view, right, _) = camera_axes(camera);
    (0..VIEW)
        .step_by(README_SAMPLED_EVERY)
        .map(|x| view * README_SCREEN_DISTANCE + right * ((x as f64 + 0.5) / HALF_VIEW - 1.0))
        .collect()
}

/// The slide's checkerboard F for squares README_SQUARE_SIZE wide, with floor: is the floor square
/// under this point an odd one?
pub fn on_an_odd_square(point: V3) -> bool {
    let square = |w: f64| (w / README_SQUARE_SIZE).floor() as i64;
    ((square(point.x) + square(point.z)) & 1) == 1
}

/// The share of the light a floor point's square shows: README_ODD_SQUARE on an odd one, else all.
pub fn square_share(point: V3) -> f64 {
    if on_an_odd_square(point) {
        README_ODD_SQUARE
    } else {
        1.0
    }
}

/// Does a floor point's green byte show a dark square? Dark is under half of what a lit white even
/// square there shows: the odd squares are far darker, the even ones that bright.
pub fn is_dark(green: u32, point: V3, light: V3) -> bool {
    let up = v3(0.0, 1.0, 0.0);
    green < byte(WHITE.y * lit_share(point, up, light)) / 2
}

/// The legend's colours by name, as the README's table and the failure messages call them.
pub const LEGEND: [(&str, u32); 8] = [
    ("BACKGROUND", BACKGROUND),
    ("CAMERA_COLOR", CAMERA_COLOR),
    ("RAY_COLOR", RAY_COLOR),
    ("MISS_COLOR", MISS_COLOR),
    ("LIGHT_COLOR", LIGHT_COLOR),
    ("SHADOW_COLOR", SHADOW_COLOR),
    ("BLOCKED_COLOR", BLOCKED_COLOR),
    ("MIRROR_COLOR", MIRROR_COLOR),
];

/// The right half of a frame: the map's pixels, row by row.
pub fn map_of(frame: &[u32]) -> Vec<u32> {
    frame
        .chunks(WIDTH)
        .flat_map(|row| row[VIEW..].to_vec())
        .collect()
}
