//! [`read_bounded`]: read a user's text file without trusting its size or kind.

use std::fs::File;
use std::io::Read as _;
use std::path::Path;

/// The limit on a TOML or XML input (problem files, experiment files, URDF, SRDF, scenes):
/// 64 MiB, hundreds of times the largest shipped one.
pub const TEXT_INPUT_LIMIT: u64 = 64 << 20;

/// Why [`read_bounded`] refused a file. Convert it into an [`std::io::Error`] (`?` or
/// `.into()`) where an error type carries the operating system's errors: the message and the
/// typed error travel inside it.
#[derive(Debug, thiserror::Error)]
pub enum BoundedReadError {
    /// The operating system could not open or read it.
    #[error("{0}")]
    Io(#[source] std::io::Error),
    /// A device, FIFO, socket or folder where a regular file is needed (`/dev/zero` never
    /// ends).
    #[error("it is not a regular file (a device, pipe or folder); give a {what}")]
    NotAFile {
        /// What the file should be, e.g. `problem file`.
        what: &'static str,
    },
    /// Larger than the limit for its kind.
    #[error("it is larger than {}, the limit for a {what}", describe_bytes(*limit))]
    TooLarge {
        /// What the file should be.
        what: &'static str,
        /// The limit in bytes.
        limit: u64,
    },
    /// Not UTF-8 text (a binary file).
    #[error("it is not text (not UTF-8 at byte {at}); a {what} is a text file")]
    NotText {
        /// What the file should be.
        what: &'static str,
        /// The offset of the first byte that is not UTF-8.
        at: usize,
    },
}

impl From<BoundedReadError> for std::io::Error {
    fn from(e: BoundedReadError) -> Self {
        match e {
            BoundedReadError::Io(source) => source,
            other => std::io::Error::new(std::io::ErrorKind::InvalidData, other),
        }
    }
}

/// `bytes` in words: `64 MiB`, `512 KiB`, `100 bytes`.
fn describe_bytes(bytes: u64) -> String {
    match bytes {
        b if b >= 1 << 20 && b % (1 << 20) == 0 => format!("{} MiB", b >> 20),
        b if b >= 1 << 10 && b % (1 << 10) == 0 => format!("{} KiB", b >> 10),
        b => format!("{b} bytes"),
    }
}

/// The text of the regular file `path` (a `what`, e.g. `"problem file"`), read only if it
/// holds at most `limit` bytes: a device such as `/dev/zero`, a FIFO or a folder is refused
/// before reading, and a file that is (or grows) larger than `limit` is refused without
/// reading more than `limit + 1` bytes.
///
/// ```
/// let dir = std::env::temp_dir().join(format!("bounded-read-doc-{}", std::process::id()));
/// std::fs::create_dir_all(&dir)?;
/// let file = dir.join("p.toml");
/// std::fs::write(&file, "name = 'x'\n")?;
/// assert_eq!(mit_star_problems::read_bounded(&file, 100, "problem file")?, "name = 'x'\n");
/// let e = mit_star_problems::read_bounded(&file, 4, "problem file").unwrap_err();
/// assert_eq!(e.to_string(), "it is larger than 4 bytes, the limit for a problem file");
/// assert!(mit_star_problems::read_bounded(&dir, 100, "problem file").is_err());
/// # std::fs::remove_dir_all(&dir)?;
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
///
/// # Errors
/// [`BoundedReadError`] saying what is wrong; the caller names the file.
pub fn read_bounded(
    path: &Path,
    limit: u64,
    what: &'static str,
) -> Result<String, BoundedReadError> {
    let bytes = read_bounded_bytes(path, limit, what)?;
    String::from_utf8(bytes).map_err(|e| BoundedReadError::NotText {
        what,
        at: e.utf8_error().valid_up_to(),
    })
}

/// The bytes of the regular file `path` (a `what`, e.g. `"point cloud file"`): the checks of
/// [`read_bounded`] (a regular file of at most `limit` bytes, never reading more than
/// `limit + 1`) for a binary input, without asking for UTF-8.
///
/// # Errors
/// [`BoundedReadError`] saying what is wrong; the caller names the file.
pub fn read_bounded_bytes(
    path: &Path,
    limit: u64,
    what: &'static str,
) -> Result<Vec<u8>, BoundedReadError> {
    let file = File::open(path).map_err(BoundedReadError::Io)?;
    let metadata = file.metadata().map_err(BoundedReadError::Io)?;
    if !metadata.is_file() {
        return Err(BoundedReadError::NotAFile { what });
    }
    if metadata.len() > limit {
        return Err(BoundedReadError::TooLarge { what, limit });
    }
    let mut bytes = Vec::with_capacity(usize::try_from(metadata.len()).unwrap_or(0));
    file.take(limit.saturating_add(1))
        .read_to_end(&mut bytes)
        .map_err(BoundedReadError::Io)?;
    if bytes.len() as u64 > limit {
        return Err(BoundedReadError::TooLarge { what, limit });
    }
    Ok(bytes)
}

/// `text` cut to at most `max` characters for quoting in an error message, with `…` and the
/// length left out when cut: a line of a 200 KB input is not echoed whole.
///
/// ```
/// assert_eq!(mit_star_problems::excerpt("short", 10), "short");
/// assert_eq!(mit_star_problems::excerpt("abcdefghij", 4), "abcd… (6 more characters)");
/// ```
pub fn excerpt(text: &str, max: usize) -> String {
    match text.char_indices().nth(max) {
        None => text.to_owned(),
        Some((at, _)) => format!(
            "{}… ({} more characters)",
            &text[..at],
            text[at..].chars().count()
        ),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn devices_folders_and_binary_files_are_refused() {
        let e = read_bounded(Path::new("/dev/zero"), 1 << 20, "problem file").unwrap_err();
        assert!(matches!(e, BoundedReadError::NotAFile { .. }), "{e}");
        let dir = std::env::temp_dir().join(format!("bounded-read-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        let e = read_bounded(&dir, 1 << 20, "path file").unwrap_err();
        assert!(e.to_string().contains("not a regular file"), "{e}");
        let binary = dir.join("b");
        std::fs::write(&binary, [b'0', b' ', 0xff, 0xfe]).unwrap();
        let e = read_bounded(&binary, 100, "path file").unwrap_err();
        assert_eq!(
            e.to_string(),
            "it is not text (not UTF-8 at byte 2); a path file is a text file"
        );
        let io: std::io::Error = e.into();
        assert_eq!(io.kind(), std::io::ErrorKind::InvalidData);
        assert!(io.to_string().contains("not UTF-8"));
        let e = read_bounded(&dir.join("missing"), 100, "path file").unwrap_err();
        assert!(matches!(e, BoundedReadError::Io(_)));
        std::fs::remove_dir_all(&dir).unwrap();
        assert_eq!(describe_bytes(TEXT_INPUT_LIMIT), "64 MiB");
    }

    #[test]
    fn excerpts_cut_on_character_boundaries() {
        assert_eq!(excerpt("ééé", 2), "éé… (1 more characters)");
        assert_eq!(excerpt("", 0), "");
    }
}
