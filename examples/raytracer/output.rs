//! Writing a [`Film`]: a tone-mapped sRGB PNG, and linear HDR as OpenEXR.

use crate::exr::write_exr;
use crate::render::Film;
use crate::tonemap::to_srgb8;
use std::fs::File;
use std::io::BufWriter;
use std::path::Path;

/// Writes the film as an 8-bit sRGB PNG, tone-mapped with `exposure` and ACES.
///
/// # Errors
/// A message naming the file.
pub fn write_png(film: &Film, path: &Path, exposure: f32) -> Result<(), String> {
    let err = |e: &dyn std::fmt::Display| format!("cannot write {}: {e}", path.display());
    let file = File::create(path).map_err(|e| err(&e))?;
    let mut encoder = png::Encoder::new(BufWriter::new(file), film.width, film.height);
    encoder.set_color(png::ColorType::Rgb);
    encoder.set_depth(png::BitDepth::Eight);
    encoder.set_source_srgb(png::SrgbRenderingIntent::Perceptual);
    let mut writer = encoder.write_header().map_err(|e| err(&e))?;
    let data: Vec<u8> = film
        .pixels
        .iter()
        .flat_map(|&p| to_srgb8(p, exposure))
        .collect();
    writer.write_image_data(&data).map_err(|e| err(&e))?;
    writer.finish().map_err(|e| err(&e))
}

/// Writes the film's linear radiance as an uncompressed 32-bit float OpenEXR file.
///
/// # Errors
/// A message naming the file.
pub fn write_hdr(film: &Film, path: &Path) -> Result<(), String> {
    let err = |e: &dyn std::fmt::Display| format!("cannot write {}: {e}", path.display());
    let file = File::create(path).map_err(|e| err(&e))?;
    let mut out = BufWriter::new(file);
    write_exr(&mut out, film.width, film.height, &film.pixels).map_err(|e| err(&e))?;
    std::io::Write::flush(&mut out).map_err(|e| err(&e))
}
