//! Machinery a student need not read: a frame to and from a PNG file, for the README's pictures
//! and for `cargo run --example frame`.
use std::fs::File;
use std::io::BufReader;

/// A frame of 0RGB pixels as 8-bit RGB bytes, row after row, as a PNG holds it.
pub fn rgb_bytes(frame: &[u32]) -> Vec<u8> {
    let bytes = |pixel: u32| [(pixel >> 16) as u8, (pixel >> 8) as u8, pixel as u8];
    frame.iter().flat_map(|&pixel| bytes(pixel)).collect()
}

/// Writes a frame `width` pixels wide as an 8-bit RGB PNG; if it cannot, says why.
pub fn write_png(path: &str, frame: &[u32], width: usize) -> Result<(), String> {
    let height = frame.len() / width;
    let file = File::create(path).map_err(|error| format!("cannot write {path}: {error}"))?;
    let mut encoder = png::Encoder::new(file, width as u32, height as u32);
    encoder.set_color(png::ColorType::Rgb);
    encoder.set_depth(png::BitDepth::Eight);
    let written = encoder
        .write_header()
        .and_then(|mut writer| writer.write_image_data(&rgb_bytes(frame)));
    written.map_err(|error| format!("cannot write {path}: {error}"))
}

/// A PNG's size and its pixels as 8-bit RGB bytes, or why it cannot be read as one.
pub fn read_png(path: &str) -> Result<((u32, u32), Vec<u8>), String> {
    let file = File::open(path).map_err(|error| format!("cannot open {path}: {error}"))?;
    let mut reader = png::Decoder::new(BufReader::new(file))
        .read_info()
        .map_err(|error| format!("{path} is not a PNG: {error}"))?;
    let info = reader.info();
    let size = (info.width, info.height);
    if info.color_type != png::ColorType::Rgb || info.bit_depth != png::BitDepth::Eight {
        return Err(format!("{path} is not an 8-bit RGB picture"));
    }
    let length = reader
        .output_buffer_size()
        .ok_or(format!("{path} is too big"))?;
    let mut rgb = vec![0; length];
    reader
        .next_frame(&mut rgb)
        .map_err(|error| format!("{path}'s pixels cannot be read: {error}"))?;
    Ok((size, rgb))
}
