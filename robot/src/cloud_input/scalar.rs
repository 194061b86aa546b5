//! The scalar types of PLY properties and PCD fields, read from bytes in either byte order.

/// Byte order of binary data.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(super) enum Endian {
    Little,
    Big,
}

/// A scalar type: signed or unsigned integers of 1, 2, 4, 8 bytes, floats of 4 or 8.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(super) enum Scalar {
    I8,
    U8,
    I16,
    U16,
    I32,
    U32,
    I64,
    U64,
    F32,
    F64,
}

impl Scalar {
    /// A PLY type name (`float`, `float32`, `uchar`, …).
    pub(super) fn from_ply(word: &str) -> Option<Self> {
        Some(match word {
            "char" | "int8" => Self::I8,
            "uchar" | "uint8" => Self::U8,
            "short" | "int16" => Self::I16,
            "ushort" | "uint16" => Self::U16,
            "int" | "int32" => Self::I32,
            "uint" | "uint32" => Self::U32,
            "float" | "float32" => Self::F32,
            "double" | "float64" => Self::F64,
            _ => return None,
        })
    }

    /// A PCD `TYPE` letter (`I`, `U`, `F`) with a `SIZE`.
    pub(super) fn from_pcd(kind: &str, size: &str) -> Option<Self> {
        Some(match (kind, size) {
            ("I", "1") => Self::I8,
            ("U", "1") => Self::U8,
            ("I", "2") => Self::I16,
            ("U", "2") => Self::U16,
            ("I", "4") => Self::I32,
            ("U", "4") => Self::U32,
            ("I", "8") => Self::I64,
            ("U", "8") => Self::U64,
            ("F", "4") => Self::F32,
            ("F", "8") => Self::F64,
            _ => return None,
        })
    }

    /// Bytes per value.
    pub(super) fn size(self) -> usize {
        match self {
            Self::I8 | Self::U8 => 1,
            Self::I16 | Self::U16 => 2,
            Self::I32 | Self::U32 | Self::F32 => 4,
            Self::I64 | Self::U64 | Self::F64 => 8,
        }
    }

    /// `true` for `F32` and `F64`.
    pub(super) fn is_float(self) -> bool {
        matches!(self, Self::F32 | Self::F64)
    }

    /// The type's name in errors.
    pub(super) fn name(self) -> &'static str {
        match self {
            Self::I8 => "int8",
            Self::U8 => "uint8",
            Self::I16 => "int16",
            Self::U16 => "uint16",
            Self::I32 => "int32",
            Self::U32 => "uint32",
            Self::I64 => "int64",
            Self::U64 => "uint64",
            Self::F32 => "float32",
            Self::F64 => "float64",
        }
    }

    /// The float at the start of `bytes` (which holds at least [`size`](Self::size) bytes);
    /// integers as their value.
    #[inline]
    pub(super) fn read(self, bytes: &[u8], endian: Endian) -> f64 {
        macro_rules! get {
            ($t:ty, $n:literal) => {{
                let mut raw = [0_u8; $n];
                raw.copy_from_slice(&bytes[..$n]);
                match endian {
                    Endian::Little => <$t>::from_le_bytes(raw),
                    Endian::Big => <$t>::from_be_bytes(raw),
                }
            }};
        }
        match self {
            Self::F32 => f64::from(get!(f32, 4)),
            Self::F64 => get!(f64, 8),
            Self::I8 => f64::from(get!(i8, 1)),
            Self::U8 => f64::from(get!(u8, 1)),
            Self::I16 => f64::from(get!(i16, 2)),
            Self::U16 => f64::from(get!(u16, 2)),
            Self::I32 => f64::from(get!(i32, 4)),
            Self::U32 => f64::from(get!(u32, 4)),
            Self::I64 => get!(i64, 8) as f64,
            Self::U64 => get!(u64, 8) as f64,
        }
    }

    /// An integer at the start of `bytes` as a count (a negative count as `u64::MAX`, which
    /// no data can hold).
    pub(super) fn read_count(self, bytes: &[u8], endian: Endian) -> u64 {
        let value = self.read(bytes, endian);
        if value < 0.0 { u64::MAX } else { value as u64 }
    }
}
