//! A minimal OpenEXR writer: one part, scan lines, no compression, 32-bit float RGB.
//!
//! The format (OpenEXR's "File Layout" document): the magic number and version, a header of
//! named attributes ended by a null byte, an offset table with one entry per scan-line
//! block, then the blocks. Uncompressed files store one scan line per block: its `y`, its
//! byte count, then each channel's row in alphabetical channel order (B, G, R). Every
//! number is little-endian. Any EXR reader opens the result (the tests read it back with the
//! `exr` crate, bit for bit).

use lobe::Vec3;
use std::io::{self, Write};

/// The file's first four bytes.
const MAGIC: u32 = 20_000_630;
/// Version 2, single-part scan-line file: no flag bits.
const VERSION: u32 = 2;
/// Pixel type FLOAT.
const FLOAT: i32 = 2;

/// Writes `pixels` (`width × height`, rows from the top, linear radiance) as an EXR file.
///
/// # Errors
/// Whatever the writer reports.
pub fn write_exr(out: &mut impl Write, width: u32, height: u32, pixels: &[Vec3]) -> io::Result<()> {
    let (w, h) = (width as usize, height as usize);
    if w == 0 || h == 0 || pixels.len() != w * h {
        return Err(io::Error::new(
            io::ErrorKind::InvalidInput,
            "image size mismatch",
        ));
    }
    let mut header = Vec::new();
    header.extend(MAGIC.to_le_bytes());
    header.extend(VERSION.to_le_bytes());
    // channels: B, G, R (alphabetical), each FLOAT, linear flag 0, sampling 1 × 1.
    let mut chlist = Vec::new();
    for name in ["B", "G", "R"] {
        chlist.extend(name.as_bytes());
        chlist.push(0);
        chlist.extend(FLOAT.to_le_bytes());
        chlist.extend([0, 0, 0, 0]); // pLinear and three reserved bytes
        chlist.extend(1i32.to_le_bytes());
        chlist.extend(1i32.to_le_bytes());
    }
    chlist.push(0);
    attribute(&mut header, "channels", "chlist", &chlist);
    attribute(&mut header, "compression", "compression", &[0]);
    let window: Vec<u8> = [0, 0, width as i32 - 1, height as i32 - 1]
        .iter()
        .flat_map(|v| v.to_le_bytes())
        .collect();
    attribute(&mut header, "dataWindow", "box2i", &window);
    attribute(&mut header, "displayWindow", "box2i", &window);
    attribute(&mut header, "lineOrder", "lineOrder", &[0]);
    attribute(
        &mut header,
        "pixelAspectRatio",
        "float",
        &1f32.to_le_bytes(),
    );
    let centre: Vec<u8> = [0f32, 0f32].iter().flat_map(|v| v.to_le_bytes()).collect();
    attribute(&mut header, "screenWindowCenter", "v2f", &centre);
    attribute(
        &mut header,
        "screenWindowWidth",
        "float",
        &1f32.to_le_bytes(),
    );
    header.push(0);

    let line_bytes = 3 * 4 * w;
    let block_bytes = 8 + line_bytes;
    let table_end = header.len() + 8 * h;
    out.write_all(&header)?;
    for y in 0..h {
        out.write_all(&((table_end + y * block_bytes) as u64).to_le_bytes())?;
    }
    let mut block = Vec::with_capacity(block_bytes);
    for (y, row) in pixels.chunks_exact(w).enumerate() {
        block.clear();
        block.extend((y as i32).to_le_bytes());
        block.extend((line_bytes as i32).to_le_bytes());
        for channel in [2, 1, 0] {
            for p in row {
                block.extend(p[channel].to_le_bytes());
            }
        }
        out.write_all(&block)?;
    }
    Ok(())
}

/// Appends the attribute `name` of type `kind` with the value bytes `value`.
fn attribute(header: &mut Vec<u8>, name: &str, kind: &str, value: &[u8]) {
    header.extend(name.as_bytes());
    header.push(0);
    header.extend(kind.as_bytes());
    header.push(0);
    header.extend((value.len() as i32).to_le_bytes());
    header.extend(value);
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn layout_of_a_tiny_image() {
        let pixels = [Vec3::new(1.0, 2.0, 3.0), Vec3::new(4.0, 5.0, 6.0)];
        let mut bytes = Vec::new();
        write_exr(&mut bytes, 2, 1, &pixels).unwrap();
        assert_eq!(&bytes[..4], &[0x76, 0x2f, 0x31, 0x01]);
        // The single offset points at the block, which ends the file.
        let block = 8 + 3 * 4 * 2;
        let table = bytes.len() - block - 8;
        let offset = u64::from_le_bytes(bytes[table..table + 8].try_into().unwrap());
        assert_eq!(offset as usize, bytes.len() - block);
        // B row first: 3, 6.
        let b0 = f32::from_le_bytes(
            bytes[offset as usize + 8..offset as usize + 12]
                .try_into()
                .unwrap(),
        );
        assert_eq!(b0, 3.0);
        assert!(write_exr(&mut Vec::new(), 3, 1, &pixels).is_err());
    }

    /// Written, then read back by an independent reader (the `exr` crate, in its strict
    /// mode): the header says what the writer meant (one 5 × 3 layer at the origin, channels
    /// B, G, R of 32-bit floats, uncompressed scan lines, increasing line order), and every
    /// value comes back bit for bit in the right pixel and channel. The values are distinct
    /// bit patterns from every corner of `f32` (zero and negative zero, subnormals, the
    /// extremes, infinities, a NaN with a payload, and arbitrary finite numbers), so that a
    /// swapped channel, a transposed image, a reversed row order or a conversion would show.
    #[test]
    fn an_exr_reader_reads_back_every_bit() {
        use ::exr::prelude::{
            Blocks, Compression, FlatSamples, LineOrder, ReadChannels, ReadLayers, read,
        };
        use std::io::Cursor;

        let (width, height) = (5_u32, 3_u32);
        let special = [
            0.0,
            -0.0,
            f32::from_bits(1),
            -f32::MIN_POSITIVE,
            f32::MAX,
            f32::MIN,
            f32::INFINITY,
            f32::NEG_INFINITY,
            f32::from_bits(0x7fc0_1234),
            1.0,
            -2.5,
            f32::EPSILON,
        ];
        // A bijective scramble of the index (odd multiplier mod 2^32): distinct patterns.
        let value = |i: u32| {
            special
                .get(i as usize)
                .copied()
                .unwrap_or_else(|| f32::from_bits(i.wrapping_mul(0x9e37_79b9) & 0x7f7f_ffff))
        };
        let pixels: Vec<Vec3> = (0..width * height)
            .map(|i| Vec3::new(value(3 * i), value(3 * i + 1), value(3 * i + 2)))
            .collect();
        let mut bytes = Vec::new();
        write_exr(&mut bytes, width, height, &pixels).unwrap();

        let image = read()
            .no_deep_data()
            .largest_resolution_level()
            .all_channels()
            .first_valid_layer()
            .all_attributes()
            .pedantic()
            .non_parallel()
            .from_buffered(Cursor::new(bytes))
            .unwrap();
        let window = image.attributes.display_window;
        assert_eq!((window.position.x(), window.position.y()), (0, 0));
        assert_eq!((window.size.width(), window.size.height()), (5, 3));
        let layer = image.layer_data;
        assert_eq!((layer.size.width(), layer.size.height()), (5, 3));
        assert_eq!(layer.encoding.compression, Compression::Uncompressed);
        assert_eq!(layer.encoding.blocks, Blocks::ScanLines);
        assert_eq!(layer.encoding.line_order, LineOrder::Increasing);
        let channels = &layer.channel_data.list;
        let names: Vec<String> = channels.iter().map(|c| c.name.to_string()).collect();
        assert_eq!(names, ["B", "G", "R"]);
        for (channel, index) in channels.iter().zip([2, 1, 0]) {
            let FlatSamples::F32(samples) = &channel.sample_data else {
                panic!("channel {} is not 32-bit float", channel.name);
            };
            assert_eq!(samples.len(), pixels.len());
            for (i, (read, written)) in samples.iter().zip(&pixels).enumerate() {
                assert_eq!(
                    read.to_bits(),
                    written[index].to_bits(),
                    "pixel ({}, {}), channel {}",
                    i % width as usize,
                    i / width as usize,
                    channel.name
                );
            }
        }
    }
}
