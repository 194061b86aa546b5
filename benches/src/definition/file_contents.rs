//! [`FileContents`]: what a file held, as an experiment records it, so that a results folder is
//! never resumed (nor an experiment re-run) with a data file that changed under the same name.

use std::fmt;
use std::io::Read;
use std::path::Path;

/// A file's length and CRC-32 (IEEE), written `"<length> bytes, crc32 <8 hex digits>"`. It
/// tells a changed file from the one recorded (a different length, or any burst of up to 32
/// changed bits, is always caught; other changes slip through with odds of 2⁻³²); it is not a
/// cryptographic digest and does not stand against a forged file.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct FileContents {
    /// Bytes in the file.
    pub length: u64,
    /// CRC-32 of the bytes.
    pub crc32: u32,
}

impl FileContents {
    /// Reads `path` in 64 KB pieces (no more in memory at a time).
    ///
    /// # Errors
    /// The read's error.
    pub fn of(path: &Path) -> std::io::Result<Self> {
        let mut file = std::fs::File::open(path)?;
        let mut hasher = crc32fast::Hasher::new();
        let mut buffer = vec![0_u8; 64 * 1024];
        let mut length = 0_u64;
        loop {
            let n = match file.read(&mut buffer) {
                Ok(0) => break,
                Ok(n) => n,
                Err(e) if e.kind() == std::io::ErrorKind::Interrupted => continue,
                Err(e) => return Err(e),
            };
            hasher.update(&buffer[..n]);
            length += n as u64;
        }
        Ok(Self {
            length,
            crc32: hasher.finalize(),
        })
    }
}

impl fmt::Display for FileContents {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{} bytes, crc32 {:08x}", self.length, self.crc32)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_changed_byte_or_length_changes_the_record() {
        let dir = std::env::temp_dir().join(format!("file-contents-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        let path = dir.join("cloud.ply");
        // The CRC-32 of the ASCII digits 1-9 is the standard check value cbf43926.
        std::fs::write(&path, b"123456789").unwrap();
        let first = FileContents::of(&path).unwrap();
        assert_eq!(first.to_string(), "9 bytes, crc32 cbf43926");
        std::fs::write(&path, b"123456780").unwrap();
        assert_ne!(FileContents::of(&path).unwrap(), first);
        std::fs::write(&path, b"1234567890").unwrap();
        assert_eq!(FileContents::of(&path).unwrap().length, 10);
        // More than one 64 KB piece.
        let big: Vec<u8> = (0..200_000_u32).map(|i| (i % 251) as u8).collect();
        std::fs::write(&path, &big).unwrap();
        let mut whole = crc32fast::Hasher::new();
        whole.update(&big);
        let read = FileContents::of(&path).unwrap();
        assert_eq!((read.length, read.crc32), (200_000, whole.finalize()));
        std::fs::remove_dir_all(&dir).unwrap();
    }
}
