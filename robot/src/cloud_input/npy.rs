//! NumPy `.npy` point clouds: a bounded reader of N×3 `float32` or `float64` arrays (either
//! byte order, C or Fortran order) and a writer of `float32` ones.

use std::path::Path;

use glam::Vec3;

use super::cloud_input_error::CloudInputError;
use super::input_cloud::{CloudFormat, PointSink, check_count};
use super::scalar::{Endian, Scalar};

const MAGIC: &[u8] = b"\x93NUMPY";

/// The bytes of a `.npy` file (version 1.0) holding `points` as an N×3 little-endian
/// `float32` array in C order: what `numpy.load` reads as `(N, 3)` `float32`.
pub fn npy_bytes(points: &[Vec3]) -> Vec<u8> {
    let dict = format!(
        "{{'descr': '<f4', 'fortran_order': False, 'shape': ({}, 3), }}",
        points.len()
    );
    // Magic (6), version (2), header length (2), then the dictionary padded with spaces and
    // ended by a newline so that the data starts at a multiple of 64 bytes.
    let unpadded = MAGIC.len() + 2 + 2 + dict.len() + 1;
    let padding = unpadded.next_multiple_of(64) - unpadded;
    let header_len = dict.len() + padding + 1;
    let mut out = Vec::with_capacity(unpadded + padding + points.len() * 12);
    out.extend(MAGIC);
    out.extend([1, 0]);
    out.extend(u16::try_from(header_len).unwrap_or(u16::MAX).to_le_bytes());
    out.extend(dict.as_bytes());
    out.extend(std::iter::repeat_n(b' ', padding));
    out.push(b'\n');
    for p in points {
        for c in p.to_array() {
            out.extend(c.to_le_bytes());
        }
    }
    out
}

/// Writes `points` to the `.npy` file `path` ([`npy_bytes`]).
///
/// # Errors
/// [`CloudInputError::Io`] if the file cannot be written.
pub fn write_npy(path: &Path, points: &[Vec3]) -> Result<(), CloudInputError> {
    std::fs::write(path, npy_bytes(points)).map_err(|source| CloudInputError::Io {
        path: path.to_owned(),
        source,
    })
}

pub(super) fn parse_npy(bytes: &[u8], origin: &str) -> Result<PointSink, CloudInputError> {
    let header_error = |message: String| CloudInputError::Header {
        origin: origin.to_owned(),
        format: CloudFormat::Npy,
        message,
    };
    let unsupported = |field: &str, message: String| CloudInputError::UnsupportedField {
        origin: origin.to_owned(),
        format: CloudFormat::Npy,
        field: field.to_owned(),
        message,
    };
    if !bytes.starts_with(MAGIC) || bytes.len() < 10 {
        return Err(header_error(
            "it does not begin with the magic `\\x93NUMPY`".into(),
        ));
    }
    let (length, start) = match bytes[6] {
        1 => (
            usize::from(u16::from_le_bytes([bytes[8], bytes[9]])),
            10_usize,
        ),
        2 | 3 => {
            let b = bytes
                .get(8..12)
                .ok_or_else(|| header_error("it ends inside the header's length".into()))?;
            (u32::from_le_bytes([b[0], b[1], b[2], b[3]]) as usize, 12)
        }
        major => return Err(header_error(format!("unknown format version {major}"))),
    };
    let dict = bytes
        .get(start..start.saturating_add(length))
        .ok_or_else(|| header_error(format!("it ends inside the {length}-byte header")))?;
    let dict =
        std::str::from_utf8(dict).map_err(|_| header_error("the header is not text".into()))?;
    let descr =
        value_of(dict, "descr").ok_or_else(|| header_error("no `descr` in the header".into()))?;
    let fortran = value_of(dict, "fortran_order")
        .ok_or_else(|| header_error("no `fortran_order` in the header".into()))?;
    let shape =
        value_of(dict, "shape").ok_or_else(|| header_error("no `shape` in the header".into()))?;
    let descr = descr.trim().trim_matches(|c| c == '\'' || c == '"');
    let (endian, scalar) = match descr.as_bytes() {
        [order @ (b'<' | b'>' | b'='), b'f', size @ (b'4' | b'8')] => (
            if *order == b'>' {
                Endian::Big
            } else {
                Endian::Little
            },
            if *size == b'4' {
                Scalar::F32
            } else {
                Scalar::F64
            },
        ),
        _ => {
            return Err(unsupported(
                "descr",
                format!(
                    "dtype `{}`: a cloud is float32 or float64 (`<f4`, `<f8`, `>f4`, `>f8`)",
                    mit_star_problems::excerpt(descr, 40)
                ),
            ));
        }
    };
    let fortran = match fortran.trim() {
        "True" => true,
        "False" => false,
        other => {
            return Err(header_error(format!(
                "fortran_order `{}`",
                mit_star_problems::excerpt(other, 20)
            )));
        }
    };
    let dims: Vec<&str> = shape
        .trim()
        .trim_start_matches('(')
        .trim_end_matches(')')
        .split(',')
        .map(str::trim)
        .filter(|d| !d.is_empty())
        .collect();
    let declared: u64 = match dims.as_slice() {
        [n, "3"] => n.parse().map_err(|_| {
            header_error(format!(
                "shape entry `{}` is not a count",
                mit_star_problems::excerpt(n, 30)
            ))
        })?,
        _ => {
            return Err(unsupported(
                "shape",
                format!(
                    "shape `{}`: a cloud is an N×3 array",
                    mit_star_problems::excerpt(shape, 40)
                ),
            ));
        }
    };
    let count = check_count(declared, origin, CloudFormat::Npy)?;
    let data = &bytes[start + length..];
    let size = scalar.size();
    let need = count * 3 * size;
    if data.len() < need {
        return Err(CloudInputError::Truncated {
            origin: origin.to_owned(),
            format: CloudFormat::Npy,
            declared,
            found: format!("holds {} bytes of the {need} needed", data.len()),
        });
    }
    if data.len() > need {
        return Err(CloudInputError::TrailingData {
            origin: origin.to_owned(),
            format: CloudFormat::Npy,
            declared,
            extra: format!("{} more bytes", data.len() - need),
        });
    }
    let mut sink = PointSink::with_capacity(count);
    if fortran {
        // Column-major: every x, then every y, then every z.
        let column = count * size;
        for i in 0..count {
            let at = |axis: usize| &data[axis * column + i * size..];
            sink.push(
                scalar.read(at(0), endian),
                scalar.read(at(1), endian),
                scalar.read(at(2), endian),
            );
        }
    } else {
        for row in data.chunks_exact(3 * size) {
            sink.push(
                scalar.read(row, endian),
                scalar.read(&row[size..], endian),
                scalar.read(&row[2 * size..], endian),
            );
        }
    }
    Ok(sink)
}

/// The text of `key`'s value in the header's Python dictionary literal: up to the next
/// top-level comma or the closing brace.
fn value_of<'a>(dict: &'a str, key: &str) -> Option<&'a str> {
    let quoted = [format!("'{key}'"), format!("\"{key}\"")];
    let at = quoted
        .iter()
        .find_map(|q| dict.find(q.as_str()).map(|i| i + q.len()))?;
    let rest = dict[at..].trim_start().strip_prefix(':')?;
    let mut depth = 0_i32;
    for (i, c) in rest.char_indices() {
        match c {
            '(' | '[' => depth += 1,
            ')' | ']' => depth -= 1,
            ',' | '}' if depth == 0 => return Some(&rest[..i]),
            _ => {}
        }
    }
    None
}
