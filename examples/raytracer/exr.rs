//! A minimal OpenEXR writer: one part, scan lines, no compression, 32-bit float RGB.
//!
//! The format (OpenEXR's "File Layout" document): the magic number and version, a header of
//! named attributes ended by a null byte, an offset table with one entry per scan-line
//! block, then the blocks. Uncompressed files store one scan line per block: its `y`, its
//! byte count, then each channel's row in alphabetical channel order (B, G, R). Every
//! number is little-endian. Any EXR reader opens the result.

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
}
