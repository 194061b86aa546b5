//! How arrays travel to the page: little-endian bytes in base64 (standard alphabet, padded),
//! which the page turns back into `Float32Array`s and `Uint32Array`s.

use serde::Serializer;

const ALPHABET: &[u8; 64] = b"ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";

/// `bytes` in base64 with padding.
pub fn base64(bytes: &[u8]) -> String {
    let mut out = String::with_capacity(bytes.len().div_ceil(3) * 4);
    for chunk in bytes.chunks(3) {
        let b = [
            chunk[0],
            chunk.get(1).copied().unwrap_or(0),
            chunk.get(2).copied().unwrap_or(0),
        ];
        let n = (u32::from(b[0]) << 16) | (u32::from(b[1]) << 8) | u32::from(b[2]);
        for (k, shift) in [18, 12, 6, 0].into_iter().enumerate() {
            if k <= chunk.len() {
                out.push(char::from(ALPHABET[((n >> shift) & 63) as usize]));
            } else {
                out.push('=');
            }
        }
    }
    out
}

/// `values` as little-endian `f32` bytes in base64; non-finite values become ±3.4e38 so the
/// page never meets a NaN.
pub(crate) fn f32s<S: Serializer>(values: &[f32], serializer: S) -> Result<S::Ok, S::Error> {
    let mut bytes = Vec::with_capacity(values.len() * 4);
    for &v in values {
        let v = if v.is_nan() {
            0.0
        } else {
            v.clamp(f32::MIN, f32::MAX)
        };
        bytes.extend_from_slice(&v.to_le_bytes());
    }
    serializer.serialize_str(&base64(&bytes))
}

/// `values` as little-endian `u32` bytes in base64.
pub(crate) fn u32s<S: Serializer>(values: &[u32], serializer: S) -> Result<S::Ok, S::Error> {
    let mut bytes = Vec::with_capacity(values.len() * 4);
    for &v in values {
        bytes.extend_from_slice(&v.to_le_bytes());
    }
    serializer.serialize_str(&base64(&bytes))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn base64_matches_the_rfc_4648_vectors() {
        for (plain, encoded) in [
            ("", ""),
            ("f", "Zg=="),
            ("fo", "Zm8="),
            ("foo", "Zm9v"),
            ("foob", "Zm9vYg=="),
            ("fooba", "Zm9vYmE="),
            ("foobar", "Zm9vYmFy"),
        ] {
            assert_eq!(base64(plain.as_bytes()), encoded);
        }
    }

    #[test]
    fn floats_are_little_endian_and_finite() {
        let mut out = Vec::new();
        let mut json = serde_json::Serializer::new(&mut out);
        f32s(&[1.0, f32::INFINITY, f32::NAN], &mut json).unwrap();
        let text = String::from_utf8(out).unwrap();
        // 1.0 = 00 00 80 3f; f32::MAX = ff ff 7f 7f; 0.0.
        let expected = base64(&[0, 0, 0x80, 0x3f, 0xff, 0xff, 0x7f, 0x7f, 0, 0, 0, 0]);
        assert_eq!(text, format!("\"{expected}\""));
    }
}
