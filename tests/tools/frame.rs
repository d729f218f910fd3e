//! `cargo run --example frame -- X Y Z YAW PITCH FILE.png`: saves the frame the window shows of the
//! demo's scene, from the eye at (X, Y, Z) turned YAW radians left and tilted PITCH up, as a PNG,
//! so that a change can be seen with no display (over SSH, say). The window's title gives the pose
//! it shows as these five numbers, to 3 decimals: given them, this saves the very frame shown.
use std::fs::File;

const USAGE: &str = "usage: cargo run --example frame -- X Y Z YAW PITCH FILE.png, e.g. \
                     0 0 0 0 -0.15 frame.png (the eye's position, then radians turned left and \
                     tilted up, as the window's title gives them)";

/// The most the window's title gives for PITCH either way: straight up or down, π/2, to 3 decimals.
const MOST_PITCH: f64 = 1.571;

/// The pose (x, y, z, yaw, pitch) and the file named by the arguments, or what is wrong with them.
fn pose(args: &[String]) -> Result<([f64; 5], &str), String> {
    let [x, y, z, yaw, pitch, path] = args else {
        let count = args.len();
        let noun = if count == 1 { "argument" } else { "arguments" };
        return Err(format!("{count} {noun}, not 6. {USAGE}"));
    };
    let number = |name: &str, text: &str| match text.parse::<f64>() {
        Ok(value) if value.is_finite() => Ok(value),
        _ => Err(format!("{name} is {text:?}, not a number. {USAGE}")),
    };
    let pitch = number("PITCH", pitch)?;
    if pitch.abs() > MOST_PITCH {
        return Err(format!(
            "PITCH is {pitch}: from -{MOST_PITCH} (straight down) to {MOST_PITCH} (straight up), \
             as the window's title gives it"
        ));
    }
    if !path.to_lowercase().ends_with(".png") {
        return Err(format!(
            "FILE is {path:?}: it is written as a PNG, so its name ends in .png"
        ));
    }
    let pose = [
        number("X", x)?,
        number("Y", y)?,
        number("Z", z)?,
        number("YAW", yaw)?,
        pitch,
    ];
    Ok((pose, path))
}

/// Writes a frame of 0RGB pixels, `width` wide, as an 8-bit RGB PNG; if it cannot, says why.
fn write_png(path: &str, frame: &[u32], width: usize) -> Result<(), String> {
    let cannot = |error: &dyn std::fmt::Display| format!("cannot write {path}: {error}");
    let file = File::create(path).map_err(|error| cannot(&error))?;
    let mut encoder = png::Encoder::new(file, width as u32, (frame.len() / width) as u32);
    encoder.set_color(png::ColorType::Rgb);
    encoder.set_depth(png::BitDepth::Eight);
    let rgb: Vec<u8> = frame
        .iter()
        .flat_map(|pixel| pixel.to_be_bytes()[1..].to_vec())
        .collect();
    let written = encoder
        .write_header()
        .and_then(|mut writer| writer.write_image_data(&rgb));
    written.map_err(|error| cannot(&error))
}

fn main() {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let saved = pose(&args).and_then(|(pose, path)| {
        let (frame, width, height) = program::demo_frame(pose);
        write_png(path, &frame, width).map(|()| format!("wrote {path}, {width} x {height} pixels"))
    });
    match saved {
        Ok(said) => println!("{said}"),
        Err(error) => {
            eprintln!("frame: {error}");
            std::process::exit(2);
        }
    }
}

/// src/main.rs in a module, as this file has a main of its own, with the one function the example
/// needs of it beside it (the program's items are private to the module).
#[allow(dead_code)]
mod program {
    include!("../../src/main.rs");

    /// The frame `render` draws of the demo from the pose [x, y, z, yaw, pitch], with its size.
    #[allow(clippy::needless_update)] // ..: any field you add to Camera as the window starts it
    pub fn demo_frame([x, y, z, yaw, pitch]: [f64; 5]) -> (Vec<u32>, usize, usize) {
        let camera = Camera {
            position: vec3(x, y, z),
            yaw,
            pitch,
            ..Camera::default()
        };
        let mut frame = vec![BACKGROUND; WIDTH * VIEW];
        render(&Scene::demo(), &camera, &mut frame);
        (frame, WIDTH, VIEW)
    }
}
