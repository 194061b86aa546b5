//! PCD point clouds (PCL's format, versions 0.6 and 0.7): a bounded reader of `ascii`,
//! `binary` and `binary_compressed` data.
//!
//! The reader takes the `x`, `y`, `z` fields (`F` of size 4 or 8, count 1) and skips every
//! other field (`rgb`, `normal_x`, PCL's `_` padding). `VIEWPOINT` is not applied, as PCL's
//! own loaders leave the points in the file's frame: give the sensor pose with
//! [`SensorPose`](super::SensorPose). `binary_compressed` data (PCL's column-wise layout,
//! compressed with LZF) is decompressed by this module's LZF decoder, its output bounded by
//! the header's size and [`MAX_CLOUD_FILE_BYTES`](super::MAX_CLOUD_FILE_BYTES).

use super::cloud_input_error::CloudInputError;
use super::input_cloud::{CloudFormat, MAX_CLOUD_FILE_BYTES, PointSink, check_count};
use super::lzf::lzf_decompress;
use super::scalar::{Endian, Scalar};

/// The longest PCD header read (bytes).
const MAX_HEADER_BYTES: usize = 1 << 20;

#[derive(Debug)]
struct Field {
    name: String,
    scalar: Scalar,
    count: usize,
}

#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Data {
    Ascii,
    Binary,
    Compressed,
}

struct Header {
    fields: Vec<Field>,
    points: u64,
    data: Data,
}

pub(super) fn parse_pcd(bytes: &[u8], origin: &str) -> Result<PointSink, CloudInputError> {
    let (header, data) = parse_header(bytes, origin)?;
    let count = check_count(header.points, origin, CloudFormat::Pcd)?;
    let axes = coordinate_fields(&header.fields, origin)?;
    let stride: usize = header
        .fields
        .iter()
        .map(|f| f.scalar.size() * f.count)
        .sum();
    let truncated = |found: String| CloudInputError::Truncated {
        origin: origin.to_owned(),
        format: CloudFormat::Pcd,
        declared: header.points,
        found,
    };
    let trailing = |extra: String| CloudInputError::TrailingData {
        origin: origin.to_owned(),
        format: CloudFormat::Pcd,
        declared: header.points,
        extra,
    };
    let data_error = |location: &str, message: String| CloudInputError::Data {
        origin: origin.to_owned(),
        format: CloudFormat::Pcd,
        location: location.to_owned(),
        message,
    };
    // Byte offset of each field within a point (binary) and its value index (ASCII).
    let offsets = starts(header.fields.iter().map(|f| f.scalar.size() * f.count));
    let need = count.checked_mul(stride);
    match header.data {
        Data::Binary => {
            let need = need.filter(|&n| n <= data.len()).ok_or_else(|| {
                truncated(format!(
                    "holds {} bytes of the {count} × {stride} needed",
                    data.len()
                ))
            })?;
            if data.len() > need {
                return Err(trailing(format!("{} more bytes", data.len() - need)));
            }
            let mut sink = PointSink::with_capacity(count);
            let [(ox, sx), (oy, sy), (oz, sz)] =
                axes.map(|a| (offsets[a], header.fields[a].scalar));
            if stride > 0 {
                for row in data.chunks_exact(stride) {
                    sink.push(
                        sx.read(&row[ox..], Endian::Little),
                        sy.read(&row[oy..], Endian::Little),
                        sz.read(&row[oz..], Endian::Little),
                    );
                }
            }
            Ok(sink)
        }
        Data::Compressed => {
            let word = |at: usize| {
                data.get(at..at + 4)
                    .map(|b| u32::from_le_bytes([b[0], b[1], b[2], b[3]]) as usize)
                    .ok_or_else(|| truncated("ends before the compressed block's sizes".into()))
            };
            let (compressed, uncompressed) = (word(0)?, word(4)?);
            if need != Some(uncompressed) {
                return Err(data_error(
                    "compressed block",
                    format!(
                        "it decompresses to {uncompressed} bytes, the header's {count} points of {stride} bytes need {}",
                        need.map_or("more than usize".into(), |n| n.to_string())
                    ),
                ));
            }
            if uncompressed as u64 > MAX_CLOUD_FILE_BYTES {
                return Err(data_error(
                    "compressed block",
                    format!(
                        "it decompresses to {uncompressed} bytes, more than the {MAX_CLOUD_FILE_BYTES} a cloud's data may have"
                    ),
                ));
            }
            let block = data.get(8..8 + compressed).ok_or_else(|| {
                truncated(format!(
                    "holds {} of the {compressed} compressed bytes",
                    data.len().saturating_sub(8)
                ))
            })?;
            if data.len() > 8 + compressed {
                return Err(trailing(format!(
                    "{} more bytes",
                    data.len() - 8 - compressed
                )));
            }
            let plain = lzf_decompress(block, uncompressed)
                .map_err(|message| data_error("compressed block", message))?;
            if plain.len() != uncompressed {
                return Err(data_error(
                    "compressed block",
                    format!(
                        "it decompresses to {} bytes, not the {uncompressed} its size says",
                        plain.len()
                    ),
                ));
            }
            // Column-wise: every point's first field, then every point's second, ….
            let column = |a: usize| offsets[a] * count;
            let [(cx, sx), (cy, sy), (cz, sz)] = axes.map(|a| (column(a), header.fields[a].scalar));
            let mut sink = PointSink::with_capacity(count);
            for i in 0..count {
                sink.push(
                    sx.read(&plain[cx + i * sx.size()..], Endian::Little),
                    sy.read(&plain[cy + i * sy.size()..], Endian::Little),
                    sz.read(&plain[cz + i * sz.size()..], Endian::Little),
                );
            }
            Ok(sink)
        }
        Data::Ascii => {
            let text = std::str::from_utf8(data).map_err(|e| {
                data_error(
                    &format!("byte {} after the header", e.valid_up_to()),
                    "ASCII data is text, this is not UTF-8".into(),
                )
            })?;
            let values = starts(header.fields.iter().map(|f| f.count));
            let width: usize = header.fields.iter().map(|f| f.count).sum();
            let columns = axes.map(|a| values[a]);
            let mut rows = text
                .lines()
                .enumerate()
                .filter(|(_, line)| !line.trim_ascii().is_empty());
            let mut sink = PointSink::with_capacity(count.min(text.len() / 6 + 1));
            for done in 0..count {
                let Some((number, line)) = rows.next() else {
                    return Err(truncated(format!("ends after {done} rows")));
                };
                let location = format!("row {} of the data", number + 1);
                let mut xyz = [0.0; 3];
                let mut seen = 0;
                for (column, word) in line.split_ascii_whitespace().enumerate() {
                    if let Some(axis) = columns.iter().position(|&c| c == column) {
                        xyz[axis] = word.parse().map_err(|_| {
                            data_error(
                                &location,
                                format!(
                                    "`{}` is not a number",
                                    mit_star_problems::excerpt(word, 40)
                                ),
                            )
                        })?;
                    }
                    seen = column + 1;
                }
                if seen != width {
                    return Err(data_error(
                        &location,
                        format!("{seen} values where the fields give {width}"),
                    ));
                }
                sink.push(xyz[0], xyz[1], xyz[2]);
            }
            let extra = rows.count();
            if extra > 0 {
                return Err(trailing(format!("{extra} more rows")));
            }
            Ok(sink)
        }
    }
}

/// The header and the data after the `DATA` line.
fn parse_header<'a>(bytes: &'a [u8], origin: &str) -> Result<(Header, &'a [u8]), CloudInputError> {
    let header_error = |message: String| CloudInputError::Header {
        origin: origin.to_owned(),
        format: CloudFormat::Pcd,
        message,
    };
    let unsupported = |field: &str, message: String| CloudInputError::UnsupportedField {
        origin: origin.to_owned(),
        format: CloudFormat::Pcd,
        field: field.to_owned(),
        message,
    };
    let window = &bytes[..bytes.len().min(MAX_HEADER_BYTES)];
    let mut start = 0;
    let mut names: Vec<&str> = Vec::new();
    let mut sizes: Vec<&str> = Vec::new();
    let mut types: Vec<&str> = Vec::new();
    let mut counts: Option<Vec<&str>> = None;
    let (mut width, mut height, mut points) = (None, None, None);
    let mut number = 0;
    let (data, data_start) = loop {
        number += 1;
        let Some(offset) = window[start..].iter().position(|&b| b == b'\n') else {
            return Err(header_error(format!(
                "no `DATA` line in the first {} bytes",
                window.len()
            )));
        };
        let raw = &window[start..start + offset];
        let line = std::str::from_utf8(raw)
            .map_err(|_| header_error(format!("line {number} is not text")))?;
        start += offset + 1;
        let mut words = line.split_ascii_whitespace();
        let Some(key) = words.next() else { continue };
        let rest: Vec<&str> = words.collect();
        let one = |what: &str| -> Result<u64, CloudInputError> {
            match rest.as_slice() {
                [value] => value.parse().map_err(|_| {
                    header_error(format!("line {number}: {what} `{value}` is not a count"))
                }),
                _ => Err(header_error(format!(
                    "line {number}: {what} takes one count"
                ))),
            }
        };
        match key {
            k if k.starts_with('#') => {}
            "VERSION" | "VIEWPOINT" => {}
            "FIELDS" | "COLUMNS" => names = rest,
            "SIZE" => sizes = rest,
            "TYPE" => types = rest,
            "COUNT" => counts = Some(rest),
            "WIDTH" => width = Some(one("WIDTH")?),
            "HEIGHT" => height = Some(one("HEIGHT")?),
            "POINTS" => points = Some(one("POINTS")?),
            "DATA" => {
                let data = match rest.as_slice() {
                    ["ascii"] => Data::Ascii,
                    ["binary"] => Data::Binary,
                    ["binary_compressed"] => Data::Compressed,
                    _ => {
                        return Err(header_error(format!(
                            "line {number}: unknown DATA `{}` (ascii, binary or binary_compressed)",
                            mit_star_problems::excerpt(&rest.join(" "), 40)
                        )));
                    }
                };
                break (data, start);
            }
            other => {
                return Err(header_error(format!(
                    "line {number}: unknown header entry `{}`",
                    mit_star_problems::excerpt(other, 40)
                )));
            }
        }
    };
    if names.is_empty() {
        return Err(header_error("no FIELDS line".into()));
    }
    let counts = counts.unwrap_or_else(|| vec!["1"; names.len()]);
    if sizes.len() != names.len() || types.len() != names.len() || counts.len() != names.len() {
        return Err(header_error(format!(
            "{} FIELDS but {} SIZE, {} TYPE and {} COUNT entries",
            names.len(),
            sizes.len(),
            types.len(),
            counts.len()
        )));
    }
    let mut fields = Vec::with_capacity(names.len());
    for (((name, size), kind), count) in names.iter().zip(&sizes).zip(&types).zip(&counts) {
        let scalar = Scalar::from_pcd(kind, size).ok_or_else(|| {
            unsupported(
                name,
                format!("unknown TYPE `{kind}` of SIZE `{size}` (I or U of 1, 2, 4, 8 bytes, F of 4 or 8)"),
            )
        })?;
        let count: usize = count
            .parse()
            .ok()
            .filter(|&c| (1..=1 << 20).contains(&c))
            .ok_or_else(|| {
                unsupported(
                    name,
                    format!("COUNT `{count}` is not a count in 1..=1048576"),
                )
            })?;
        fields.push(Field {
            name: (*name).to_owned(),
            scalar,
            count,
        });
    }
    let area = match (width, height) {
        (Some(w), Some(h)) => w.checked_mul(h),
        (Some(w), None) => Some(w),
        _ => return Err(header_error("no WIDTH line".into())),
    };
    let points = points.or(area).unwrap_or(u64::MAX);
    if area.is_some_and(|a| a != points) {
        return Err(header_error(format!(
            "POINTS {points} is not WIDTH × HEIGHT ({})",
            area.unwrap_or(0)
        )));
    }
    Ok((
        Header {
            fields,
            points,
            data,
        },
        &bytes[data_start..],
    ))
}

/// The indices of the `x`, `y`, `z` fields.
fn coordinate_fields(fields: &[Field], origin: &str) -> Result<[usize; 3], CloudInputError> {
    let mut out = [0; 3];
    for (slot, axis) in out.iter_mut().zip(["x", "y", "z"]) {
        let unsupported = |message: String| CloudInputError::UnsupportedField {
            origin: origin.to_owned(),
            format: CloudFormat::Pcd,
            field: axis.to_owned(),
            message,
        };
        let index = fields
            .iter()
            .position(|f| f.name == axis)
            .ok_or_else(|| unsupported("there is no such field".into()))?;
        let field = &fields[index];
        if !field.scalar.is_float() || field.count != 1 {
            return Err(unsupported(format!(
                "a coordinate must be one F of size 4 or 8, not {} × {}",
                field.count,
                field.scalar.name()
            )));
        }
        *slot = index;
    }
    Ok(out)
}

/// Where each of consecutive items of these sizes starts: 0, then the running sums.
fn starts(sizes: impl Iterator<Item = usize>) -> Vec<usize> {
    sizes
        .scan(0, |at, size| {
            let here = *at;
            *at += size;
            Some(here)
        })
        .collect()
}
