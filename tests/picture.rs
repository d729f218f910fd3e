//! The README's two pictures are frames `render` draws of the demo scene, both halves: from the start
//! pose, and from the start pose pitched down 0.15 radians. These tests compare the program's output
//! with a stored earlier output: they keep the pictures true, while the other tests check the
//! rendering itself. When a frame changes on purpose, write the pictures anew with
//! `UPDATE_PICTURE=1 cargo test --test picture` (which then compares nothing), and look at them
//! before committing them.
#[allow(dead_code)]
#[path = "../src/main.rs"]
mod raytracer;

use raytracer::*;
use std::fs::File;
use std::io::BufReader;

/// A frame of 0RGB pixels as 8-bit RGB bytes, row after row.
fn rgb_bytes(frame: &[u32]) -> Vec<u8> {
    let bytes = |pixel: u32| [(pixel >> 16) as u8, (pixel >> 8) as u8, pixel as u8];
    frame.iter().flat_map(|&pixel| bytes(pixel)).collect()
}

fn write_picture(path: &str, rgb: &[u8]) {
    let file = File::create(path).expect("the picture can be written");
    let mut encoder = png::Encoder::new(file, WIDTH as u32, VIEW as u32);
    encoder.set_color(png::ColorType::Rgb);
    encoder.set_depth(png::BitDepth::Eight);
    let mut writer = encoder.write_header().expect("a PNG header");
    writer.write_image_data(rgb).expect("the picture's pixels");
}

fn read_picture(path: &str) -> Vec<u8> {
    let file = File::open(path).expect("the picture is there");
    let mut reader = png::Decoder::new(BufReader::new(file))
        .read_info()
        .expect("a PNG");
    let info = reader.info();
    // Not a check of the program: a stored picture of another shape or format would be compared
    // out of step, pixel against the wrong pixel.
    assert_eq!(info.width as usize, WIDTH, "the picture's width");
    assert_eq!(info.height as usize, VIEW, "the picture's height");
    assert_eq!(info.color_type, png::ColorType::Rgb, "RGB");
    assert_eq!(info.bit_depth, png::BitDepth::Eight, "8 bits a channel");
    let mut rgb = vec![
        0;
        reader
            .output_buffer_size()
            .expect("a size that fits in memory")
    ];
    reader.next_frame(&mut rgb).expect("the picture's pixels");
    rgb
}

/// Renders the demo from `camera` and compares it with the picture in `tests/` named `name`.
fn assert_picture_is_the_frame(name: &str, camera: &Camera) {
    let path = format!("{}/tests/{name}", env!("CARGO_MANIFEST_DIR"));
    let mut frame = vec![0; WIDTH * VIEW];
    render(&Scene::default(), camera, &mut frame);
    let rendered = rgb_bytes(&frame);
    if std::env::var_os("UPDATE_PICTURE").is_some() {
        write_picture(&path, &rendered);
        println!("wrote tests/{name}: look at it before committing it");
        return; // nothing to compare: the picture is the frame just written
    }
    let picture = read_picture(&path);
    let differing = (rendered.chunks(3).zip(picture.chunks(3))).filter(|(a, b)| a != b);
    let count = differing.count();
    assert_eq!(
        count, 0,
        "{count} pixels differ from tests/{name}; if the change is meant, write it anew \
         with UPDATE_PICTURE=1 cargo test --test picture"
    );
}

#[test]
fn the_readme_picture_is_the_default_frame() {
    assert_picture_is_the_frame("default_frame.png", &Camera::default());
}

#[test]
fn the_readme_pitched_picture_is_the_start_pose_pitched_down() {
    let pitched = Camera {
        pitch: -0.15,
        ..Camera::default()
    };
    assert_picture_is_the_frame("pitched_frame.png", &pitched);
}
