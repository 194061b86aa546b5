//! LZF decompression (Marc Lehmann's liblzf format, as PCL's `binary_compressed` uses):
//! bounded by the expected size, refusing corrupt streams instead of reading past them.

/// Decompresses `input`, refusing to produce more than `limit` bytes.
///
/// The stream is a sequence of chunks: a control byte below 32 starts a run of
/// `control + 1` literal bytes; otherwise its top three bits are a length (7: add the next
/// byte) and the back-reference's offset is its low five bits and the next byte.
pub(super) fn lzf_decompress(input: &[u8], limit: usize) -> Result<Vec<u8>, String> {
    // A chunk of three bytes gives at most 264: no stream expands more than 88 times.
    let mut out = Vec::with_capacity(limit.min(input.len().saturating_mul(88)));
    let mut ip = 0;
    while ip < input.len() {
        let control = usize::from(input[ip]);
        ip += 1;
        if control < 32 {
            let run = control + 1;
            let literal = input.get(ip..ip + run).ok_or_else(|| {
                format!("a literal run of {run} bytes ends past the data at byte {ip}")
            })?;
            if out.len() + run > limit {
                return Err(format!("it decompresses to more than {limit} bytes"));
            }
            out.extend_from_slice(literal);
            ip += run;
        } else {
            let mut length = control >> 5;
            if length == 7 {
                length += usize::from(
                    *input
                        .get(ip)
                        .ok_or("the stream ends inside a back-reference")?,
                );
                ip += 1;
            }
            let low = usize::from(
                *input
                    .get(ip)
                    .ok_or("the stream ends inside a back-reference")?,
            );
            ip += 1;
            let back = ((control & 0x1f) << 8) + low + 1;
            let from = out.len().checked_sub(back).ok_or_else(|| {
                format!(
                    "a back-reference {back} bytes back at output byte {}",
                    out.len()
                )
            })?;
            let length = length + 2;
            if out.len() + length > limit {
                return Err(format!("it decompresses to more than {limit} bytes"));
            }
            // Byte by byte: the source may overlap what is being written.
            for k in 0..length {
                let byte = out[from + k];
                out.push(byte);
            }
        }
    }
    Ok(out)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn literals_and_overlapping_back_references() {
        // "abc" as a literal, then a back-reference of length 7 (3 bits 5 → 5 + 2) one byte
        // back... here 3 back: "abcabcabca".
        let stream = [2, b'a', b'b', b'c', (5 << 5), 2];
        assert_eq!(lzf_decompress(&stream, 100).unwrap(), b"abcabcabca");
        // The long form: length 7 + extra.
        let stream = [0, b'z', (7 << 5), 1, 0];
        assert_eq!(lzf_decompress(&stream, 100).unwrap(), vec![b'z'; 11]);
    }

    #[test]
    fn corrupt_streams_are_refused() {
        assert!(
            lzf_decompress(&[5, b'a'], 100)
                .unwrap_err()
                .contains("literal run")
        );
        assert!(
            lzf_decompress(&[0, b'a', (1 << 5), 9], 100)
                .unwrap_err()
                .contains("back-reference")
        );
        assert!(
            lzf_decompress(&[0, b'a', (7 << 5)], 100)
                .unwrap_err()
                .contains("ends inside")
        );
        assert!(
            lzf_decompress(&[0, b'a', (7 << 5), 255, 0], 10)
                .unwrap_err()
                .contains("more than 10")
        );
    }
}
