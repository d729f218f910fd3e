//! `cargo run --example frame -- X Y Z YAW PITCH FILE.png`: saves the frame the window would show
//! of the demo's scene, from the eye at (X, Y, Z) turned YAW radians left and tilted PITCH up, as
//! a PNG, so that a change can be seen with no display (over SSH, say).
use std::f64::consts::FRAC_PI_2;

#[allow(dead_code)]
#[path = "../support/picture.rs"]
mod picture;

const USAGE: &str = "usage: cargo run --example frame -- X Y Z YAW PITCH FILE.png, e.g. \
                     0 0 0 0 -0.15 frame.png (the eye's position, then radians turned left and \
                     tilted up)";

/// The pose (x, y, z, yaw, pitch) and the file named by the arguments, or what is wrong with them.
fn pose(args: &[String]) -> Result<([f64; 5], &str), String> {
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
    let pose = [
        number("X", x)?,
        number("Y", y)?,
        number("Z", z)?,
        number("YAW", yaw)?,
        pitch,
    ];
    Ok((pose, path))
}

fn main() {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let saved = pose(&args).and_then(|(pose, path)| {
        let (frame, width, height) = program::demo_frame(pose);
        picture::write_png(path, &frame, width)
            .map(|()| format!("wrote {path}, {width} x {height} pixels"))
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
    pub fn demo_frame([x, y, z, yaw, pitch]: [f64; 5]) -> (Vec<u32>, usize, usize) {
        let camera = Camera {
            position: vec3(x, y, z),
            yaw,
            pitch,
        };
        let mut frame = vec![BACKGROUND; WIDTH * VIEW];
        render(&Scene::default(), &camera, &mut frame);
        (frame, WIDTH, VIEW)
    }
}
