//! PLY point clouds: a bounded reader (ASCII, binary little and big endian); the writer is
//! `ply_writer.rs`.
//!
//! The reader takes the `vertex` element's `x`, `y`, `z` (each `float` or `double`) and skips
//! every other property (colours, normals, lists) and every other element (faces), walking
//! binary lists by their counts. Counts are checked against
//! [`MAX_CLOUD_POINTS`](super::MAX_CLOUD_POINTS) and, for binary data, against the bytes
//! there are before anything is allocated.

use super::cloud_input_error::CloudInputError;
use super::input_cloud::{CloudFormat, PointSink, check_count};
use super::scalar::{Endian, Scalar};

/// The longest PLY header read (bytes).
const MAX_HEADER_BYTES: usize = 1 << 20;

/// A property of an element.
#[derive(Debug, Clone)]
enum Property {
    Scalar(Scalar, String),
    List { count: Scalar, item: Scalar },
}

#[derive(Debug)]
struct Element {
    name: String,
    count: u64,
    properties: Vec<Property>,
}

impl Element {
    /// The size of one instance if it has no list, else `None`.
    fn fixed_size(&self) -> Option<usize> {
        self.properties
            .iter()
            .map(|p| match p {
                Property::Scalar(s, _) => Some(s.size()),
                Property::List { .. } => None,
            })
            .sum()
    }

    /// The fewest bytes one instance takes (≥ 1 unless it has no property).
    fn min_size(&self) -> usize {
        self.properties
            .iter()
            .map(|p| match p {
                Property::Scalar(s, _) => s.size(),
                Property::List { count, .. } => count.size(),
            })
            .sum()
    }
}

/// `None` for ASCII.
type Encoding = Option<Endian>;

pub(super) fn parse_ply(bytes: &[u8], origin: &str) -> Result<PointSink, CloudInputError> {
    let header_error = |message: String| CloudInputError::Header {
        origin: origin.to_owned(),
        format: CloudFormat::Ply,
        message,
    };
    let (encoding, elements, data) = parse_header(bytes).map_err(header_error)?;
    let Some(vertex) = elements.iter().position(|e| e.name == "vertex") else {
        return Err(header_error("no `vertex` element".into()));
    };
    let axes = coordinate_slots(&elements[vertex], origin)?;
    let declared = elements[vertex].count;
    let count = check_count(declared, origin, CloudFormat::Ply)?;
    let reader = Reader {
        origin,
        declared,
        elements: &elements,
        vertex,
        axes,
        count,
    };
    match encoding {
        None => {
            let text = std::str::from_utf8(data).map_err(|e| CloudInputError::Data {
                origin: origin.to_owned(),
                format: CloudFormat::Ply,
                location: format!("byte {} after the header", e.valid_up_to()),
                message: "an ASCII PLY's data is text, this is not UTF-8".into(),
            })?;
            reader.ascii(text)
        }
        Some(endian) => reader.binary(data, endian),
    }
}

/// The format, the elements and the data after `end_header`'s line.
fn parse_header(bytes: &[u8]) -> Result<(Encoding, Vec<Element>, &[u8]), String> {
    if !bytes.starts_with(b"ply") {
        return Err("it does not begin with `ply`".into());
    }
    let window = &bytes[..bytes.len().min(MAX_HEADER_BYTES)];
    let mut end = None;
    let mut start = 0;
    while let Some(offset) = window[start..].iter().position(|&b| b == b'\n') {
        let line = &window[start..start + offset];
        if line.strip_suffix(b"\r").unwrap_or(line).trim_ascii() == b"end_header" {
            end = Some((start, start + offset + 1));
            break;
        }
        start += offset + 1;
    }
    let Some((header_end, data_start)) = end else {
        return Err(format!(
            "no `end_header` line in the first {} bytes",
            window.len()
        ));
    };
    let text = std::str::from_utf8(&bytes[..header_end])
        .map_err(|e| format!("the header is not text (byte {})", e.valid_up_to()))?;
    let mut encoding = None;
    let mut elements: Vec<Element> = Vec::new();
    for (index, line) in text.lines().enumerate().skip(1) {
        let number = index + 1;
        let words: Vec<&str> = line.split_ascii_whitespace().collect();
        match words.as_slice() {
            [] | ["comment", ..] | ["obj_info", ..] => {}
            ["format", kind, _version] => {
                encoding = Some(match *kind {
                    "ascii" => None,
                    "binary_little_endian" => Some(Endian::Little),
                    "binary_big_endian" => Some(Endian::Big),
                    other => return Err(format!("line {number}: unknown format `{other}`")),
                });
            }
            ["element", name, count] => elements.push(Element {
                name: (*name).to_owned(),
                count: count.parse().map_err(|_| {
                    format!("line {number}: element `{name}` count `{count}` is not a count")
                })?,
                properties: Vec::new(),
            }),
            ["property", "list", count, item, _name] => {
                let element = elements
                    .last_mut()
                    .ok_or_else(|| format!("line {number}: a property before any element"))?;
                let scalar = |word: &str| {
                    Scalar::from_ply(word)
                        .ok_or_else(|| format!("line {number}: unknown property type `{word}`"))
                };
                let count = scalar(count)?;
                if count.is_float() {
                    return Err(format!(
                        "line {number}: a list's count must be an integer type"
                    ));
                }
                element.properties.push(Property::List {
                    count,
                    item: scalar(item)?,
                });
            }
            ["property", kind, name] => {
                let element = elements
                    .last_mut()
                    .ok_or_else(|| format!("line {number}: a property before any element"))?;
                let scalar = Scalar::from_ply(kind)
                    .ok_or_else(|| format!("line {number}: unknown property type `{kind}`"))?;
                element
                    .properties
                    .push(Property::Scalar(scalar, (*name).to_owned()));
            }
            _ => {
                return Err(format!(
                    "line {number}: cannot read `{}`",
                    mit_star_problems::excerpt(line, 80)
                ));
            }
        }
    }
    let encoding = encoding.ok_or("no `format` line")?;
    Ok((encoding, elements, &bytes[data_start..]))
}

/// The property indices of `x`, `y`, `z` in the vertex element.
fn coordinate_slots(vertex: &Element, origin: &str) -> Result<[usize; 3], CloudInputError> {
    let mut slots = [usize::MAX; 3];
    for (slot, axis) in slots.iter_mut().zip(["x", "y", "z"]) {
        let found = vertex
            .properties
            .iter()
            .position(|p| matches!(p, Property::Scalar(_, name) if name == axis));
        let unsupported = |message: String| CloudInputError::UnsupportedField {
            origin: origin.to_owned(),
            format: CloudFormat::Ply,
            field: axis.to_owned(),
            message,
        };
        let index =
            found.ok_or_else(|| unsupported("the vertex element has no such property".into()))?;
        let scalar = scalar_of(vertex, index);
        if !scalar.is_float() {
            return Err(unsupported(format!(
                "a coordinate must be `float` or `double`, not {}",
                scalar.name()
            )));
        }
        *slot = index;
    }
    Ok(slots)
}

struct Reader<'a> {
    origin: &'a str,
    declared: u64,
    elements: &'a [Element],
    vertex: usize,
    axes: [usize; 3],
    count: usize,
}

impl Reader<'_> {
    fn truncated(&self, found: String) -> CloudInputError {
        CloudInputError::Truncated {
            origin: self.origin.to_owned(),
            format: CloudFormat::Ply,
            declared: self.declared,
            found,
        }
    }

    fn binary(&self, data: &[u8], endian: Endian) -> Result<PointSink, CloudInputError> {
        let mut at = 0_usize;
        let mut sink = PointSink::with_capacity(0);
        for (index, element) in self.elements.iter().enumerate() {
            let left = data.len() - at;
            if index == self.vertex {
                let capacity = match element.min_size() {
                    0 => 0,
                    min => self.count.min(left / min),
                };
                sink = PointSink::with_capacity(capacity);
            }
            if let Some(size) = element.fixed_size() {
                let need = usize::try_from(element.count)
                    .ok()
                    .and_then(|n| n.checked_mul(size))
                    .filter(|&need| need <= left)
                    .ok_or_else(|| {
                        self.truncated(format!(
                            "holds {left} bytes where element `{}` needs {} × {size}",
                            element.name, element.count
                        ))
                    })?;
                if index == self.vertex && size > 0 {
                    let offsets = self.axes.map(|a| scalar_offset(element, a));
                    let [sx, sy, sz] = self.axes.map(|a| scalar_of(element, a));
                    for row in data[at..at + need].chunks_exact(size) {
                        sink.push(
                            sx.read(&row[offsets[0]..], endian),
                            sy.read(&row[offsets[1]..], endian),
                            sz.read(&row[offsets[2]..], endian),
                        );
                    }
                }
                at += need;
            } else {
                // Lists: walk each instance. Each takes at least one byte (its list count), so
                // the walk ends within the data whatever the declared count.
                let mut xyz = [0.0; 3];
                let mut done = 0_u64;
                while done < element.count {
                    for (p, property) in element.properties.iter().enumerate() {
                        match property {
                            Property::Scalar(scalar, _) => {
                                let value = data
                                    .get(at..at + scalar.size())
                                    .ok_or_else(|| self.ended(element, done))?;
                                let axis = self.axes.iter().position(|&a| a == p);
                                if let (true, Some(axis)) = (index == self.vertex, axis) {
                                    xyz[axis] = scalar.read(value, endian);
                                }
                                at += scalar.size();
                            }
                            Property::List { count, item } => {
                                let value = data
                                    .get(at..at + count.size())
                                    .ok_or_else(|| self.ended(element, done))?;
                                let n = count.read_count(value, endian);
                                let skip = usize::try_from(n)
                                    .ok()
                                    .and_then(|n| n.checked_mul(item.size()))
                                    .filter(|&s| s <= data.len() - at - count.size())
                                    .ok_or_else(|| self.ended(element, done))?;
                                at += count.size() + skip;
                            }
                        }
                    }
                    if index == self.vertex {
                        sink.push(xyz[0], xyz[1], xyz[2]);
                    }
                    done += 1;
                }
            }
        }
        if at < data.len() {
            return Err(CloudInputError::TrailingData {
                origin: self.origin.to_owned(),
                format: CloudFormat::Ply,
                declared: self.declared,
                extra: format!("{} more bytes", data.len() - at),
            });
        }
        Ok(sink)
    }

    fn ended(&self, element: &Element, done: u64) -> CloudInputError {
        self.truncated(format!(
            "ends inside element `{}` after {done} of its {} instances",
            element.name, element.count
        ))
    }

    fn ascii(&self, text: &str) -> Result<PointSink, CloudInputError> {
        let mut lines = text
            .lines()
            .enumerate()
            .filter(|(_, line)| !line.trim_ascii().is_empty());
        let mut sink = PointSink::with_capacity(0);
        for (index, element) in self.elements.iter().enumerate() {
            let is_vertex = index == self.vertex;
            if is_vertex {
                sink = PointSink::with_capacity(self.count.min(text.len() / 6 + 1));
            }
            let mut done = 0_u64;
            while done < element.count {
                let Some((number, line)) = lines.next() else {
                    return Err(self.truncated(format!(
                        "ends after {done} of the {} rows of element `{}`",
                        element.count, element.name
                    )));
                };
                let data_error = |message: String| CloudInputError::Data {
                    origin: self.origin.to_owned(),
                    format: CloudFormat::Ply,
                    location: format!("row {} of the data", number + 1),
                    message,
                };
                let mut words = line.split_ascii_whitespace();
                let mut xyz = [0.0; 3];
                for (p, property) in element.properties.iter().enumerate() {
                    let mut word = || {
                        words.next().ok_or_else(|| {
                            data_error(format!(
                                "fewer values than element `{}`'s properties",
                                element.name
                            ))
                        })
                    };
                    match property {
                        Property::Scalar(..) => {
                            let w = word()?;
                            let axis = self.axes.iter().position(|&a| a == p);
                            if let (true, Some(axis)) = (is_vertex, axis) {
                                xyz[axis] = w.parse().map_err(|_| {
                                    data_error(format!(
                                        "`{}` is not a number",
                                        mit_star_problems::excerpt(w, 40)
                                    ))
                                })?;
                            }
                        }
                        Property::List { .. } => {
                            let w = word()?;
                            let n: usize = w.parse().map_err(|_| {
                                data_error(format!(
                                    "list count `{}` is not a count",
                                    mit_star_problems::excerpt(w, 40)
                                ))
                            })?;
                            for _ in 0..n {
                                word()?;
                            }
                        }
                    }
                }
                if words.next().is_some() {
                    return Err(data_error(format!(
                        "more values than element `{}`'s {} properties",
                        element.name,
                        element.properties.len()
                    )));
                }
                if is_vertex {
                    sink.push(xyz[0], xyz[1], xyz[2]);
                }
                done += 1;
            }
        }
        let extra = lines.count();
        if extra > 0 {
            return Err(CloudInputError::TrailingData {
                origin: self.origin.to_owned(),
                format: CloudFormat::Ply,
                declared: self.declared,
                extra: format!("{extra} more rows"),
            });
        }
        Ok(sink)
    }
}

/// The byte offset of scalar property `index` in a fixed-size instance.
fn scalar_offset(element: &Element, index: usize) -> usize {
    element.properties[..index]
        .iter()
        .map(|p| match p {
            Property::Scalar(s, _) => s.size(),
            Property::List { .. } => 0,
        })
        .sum()
}

fn scalar_of(element: &Element, index: usize) -> Scalar {
    match &element.properties[index] {
        Property::Scalar(s, _) => *s,
        Property::List { item, .. } => *item,
    }
}
