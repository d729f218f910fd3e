//! `cargo run --example frame -- X Y Z YAW PITCH FILE.png`: saves the frame the window would show
//! of the demo's scene, from the eye at (X, Y, Z) turned YAW radians left and tilted PITCH up, as
//! a PNG, so that a change can be seen with no display (over SSH, say).
#[allow(dead_code)]
#[path = "../support/picture.rs"]
mod picture;
#[allow(dead_code)]
#[path = "../../src/main.rs"]
mod raytracer;

use raytracer::*;
use std::f64::consts::FRAC_PI_2;

const USAGE: &str = "usage: cargo run --example frame -- X Y Z YAW PITCH FILE.png, e.g. \
                     0 0 0 0 -0.15 frame.png (the eye's position, then radians turned left and \
                     tilted up)";

/// The pose and the file named by the arguments, or what is wrong with them.
fn pose(args: &[String]) -> Result<(Camera, &str), String> {
    let [x, y, z, yaw, pitch, path] = args else {
        return Err(format!("{} arguments, not 6. {USAGE}", args.len()));
    };
    let number = |name: &str, text: &str| match text.parse::<f64>() {
        Ok(value) if value.is_finite() => Ok(value),
        _ => Err(format!("{name} is {text:?}, not a number. {USAGE}")),
    };
    let pitch = number("PITCH", pitch)?;
    if pitch.abs() > FRAC_PI_2 {
        return Err(format!(
            "PITCH is {pitch}: from -{FRAC_PI_2:.4} (straight down) to {FRAC_PI_2:.4} (straight \
             up), as the window allows"
        ));
    }
    let camera = Camera {
        position: vec3(number("X", x)?, number("Y", y)?, number("Z", z)?),
        yaw: number("YAW", yaw)?,
        pitch,
    };
    Ok((camera, path))
}

fn main() {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let saved = pose(&args).and_then(|(camera, path)| {
        let mut frame = vec![BACKGROUND; WIDTH * VIEW];
        render(&Scene::default(), &camera, &mut frame);
        picture::write_png(path, &frame).map(|()| path)
    });
    match saved {
        Ok(path) => println!("wrote {path}, {WIDTH} x {VIEW} pixels"),
        Err(error) => {
            eprintln!("frame: {error}");
            std::process::exit(2);
        }
    }
}
