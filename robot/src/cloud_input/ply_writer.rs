//! Writing PLY point clouds: [`write_ply`] and [`ply_bytes`].

use std::path::Path;

use glam::Vec3;

use super::cloud_input_error::CloudInputError;

/// How [`write_ply`] encodes the points.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum PlyEncoding {
    /// Text, one point a line (exact: `f32`'s shortest round-trip decimal form).
    Ascii,
    /// Binary, little endian (what most tools write).
    BinaryLittleEndian,
    /// Binary, big endian.
    BinaryBigEndian,
}

/// The bytes of a PLY file holding `points` as one `vertex` element of `float` `x`, `y`, `z`.
pub fn ply_bytes(points: &[Vec3], encoding: PlyEncoding) -> Vec<u8> {
    let format = match encoding {
        PlyEncoding::Ascii => "ascii",
        PlyEncoding::BinaryLittleEndian => "binary_little_endian",
        PlyEncoding::BinaryBigEndian => "binary_big_endian",
    };
    let mut out = format!(
        "ply\nformat {format} 1.0\ncomment written by mit-star\nelement vertex {}\n\
         property float x\nproperty float y\nproperty float z\nend_header\n",
        points.len()
    )
    .into_bytes();
    match encoding {
        PlyEncoding::Ascii => {
            use std::fmt::Write as _;
            let mut text = String::with_capacity(points.len() * 30);
            for p in points {
                let _ = writeln!(text, "{} {} {}", p.x, p.y, p.z);
            }
            out.extend(text.as_bytes());
        }
        PlyEncoding::BinaryLittleEndian => {
            out.reserve(points.len() * 12);
            for p in points {
                for c in p.to_array() {
                    out.extend(c.to_le_bytes());
                }
            }
        }
        PlyEncoding::BinaryBigEndian => {
            out.reserve(points.len() * 12);
            for p in points {
                for c in p.to_array() {
                    out.extend(c.to_be_bytes());
                }
            }
        }
    }
    out
}

/// Writes `points` to the PLY file `path` ([`ply_bytes`]).
///
/// # Errors
/// [`CloudInputError::Io`] if the file cannot be written.
pub fn write_ply(
    path: &Path,
    points: &[Vec3],
    encoding: PlyEncoding,
) -> Result<(), CloudInputError> {
    std::fs::write(path, ply_bytes(points, encoding)).map_err(|source| CloudInputError::Io {
        path: path.to_owned(),
        source,
    })
}
