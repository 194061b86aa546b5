//! [`FolderLock`]: one writing process per results folder.
//!
//! A results folder is written by one process at a time. The writer holds an exclusive
//! advisory lock (`flock`) on the folder's [`LOCK_FILE`]; readers hold a shared one while they
//! read. The operating system releases a lock when its holder exits, however it exits
//! (SIGKILL, a crash, a job's time limit), so a dead writer never leaves a stale lock behind:
//! the file stays, the lock does not.
//!
//! Within one process, locks of one folder are shared: a `bench` holds the folder through its
//! [`ResultsFolder`](crate::ResultsFolder), and its [`RunJournal`](crate::RunJournal) and
//! rebuild run under the same lock instead of refusing each other.

use std::fs::{File, OpenOptions};
use std::io::{Read as _, Seek as _, SeekFrom, Write as _};
use std::path::{Path, PathBuf};
use std::sync::{Arc, Mutex, Weak};
use std::time::{Duration, Instant};

use fs4::{FileExt, TryLockError};

use crate::error::HarnessError;

/// The name of the lock file in a results folder.
pub(crate) const LOCK_FILE: &str = ".mit-star.lock";

/// How long a writer waits for readers (`compare`, `merge` reading its parts) to finish
/// before it gives up.
const READERS_PATIENCE: Duration = Duration::from_secs(10);

/// A held lock of a results folder; released when the last clone is dropped.
#[derive(Debug, Clone)]
pub(crate) struct FolderLock(Arc<Held>);

/// The open lock file and how it is held.
#[derive(Debug)]
struct Held {
    file: File,
    exclusive: bool,
}

impl Drop for Held {
    fn drop(&mut self) {
        if self.exclusive {
            // Leave no holder behind for the next diagnosis; closing the file releases the lock.
            let _ = self.file.set_len(0);
        }
    }
}

/// Locks held by this process, by canonical folder. The folder is kept beside each weak
/// reference so that a lookup upgrades only the lock it is after: upgrading every entry to
/// read its folder made a lookup of one folder a holder, for a moment, of all the others, and
/// a lock dropped in that moment outlived its last clone.
static HELD: Mutex<Vec<(PathBuf, Weak<Held>)>> = Mutex::new(Vec::new());

impl FolderLock {
    /// Takes `folder` (which must exist) for writing: waits a little for readers, refuses
    /// another writer. Records this process's id and command line in the lock file for the
    /// error another writer gets.
    ///
    /// # Errors
    /// [`HarnessError::FolderLocked`] if another process holds the folder;
    /// [`HarnessError::OutputFolder`] if the lock file cannot be created or locked.
    pub(crate) fn exclusive(folder: &Path) -> Result<Self, HarnessError> {
        let fail = |source| HarnessError::OutputFolder {
            path: folder.to_path_buf(),
            source,
        };
        let canonical = folder.canonicalize().map_err(fail)?;
        let mut held = HELD
            .lock()
            .unwrap_or_else(std::sync::PoisonError::into_inner);
        if let Some(lock) = find(&mut held, &canonical) {
            if lock.0.exclusive {
                return Ok(lock);
            }
            return Err(HarnessError::FolderLocked {
                path: folder.to_path_buf(),
                pid: Some(std::process::id()),
                holder: "this process, which is reading it".into(),
                advice: "a folder cannot be written while it is read".into(),
            });
        }
        let path = canonical.join(LOCK_FILE);
        let mut file = OpenOptions::new()
            .read(true)
            .write(true)
            .create(true)
            .truncate(false)
            .open(&path)
            .map_err(fail)?;
        let started = Instant::now();
        loop {
            match FileExt::try_lock(&file) {
                Ok(()) => break,
                Err(TryLockError::Error(source)) => return Err(fail(source)),
                Err(TryLockError::WouldBlock) => {}
            }
            if let Some((pid, holder)) = writer(&path)? {
                return Err(HarnessError::FolderLocked {
                    path: folder.to_path_buf(),
                    pid,
                    holder,
                    advice: "wait for it to finish (or stop it), or write to another \
                             --output folder; the lock is released when that process exits, \
                             even if it is killed"
                        .into(),
                });
            }
            if started.elapsed() > READERS_PATIENCE {
                return Err(HarnessError::FolderLocked {
                    path: folder.to_path_buf(),
                    pid: None,
                    holder: "another mit-star process reading it (`compare` or `merge`)".into(),
                    advice: "try again when it has finished reading".into(),
                });
            }
            std::thread::sleep(Duration::from_millis(50));
        }
        let record = format!(
            "{}\n{} on {}\n",
            std::process::id(),
            command_line(),
            crate::MachineInfo::detect().hostname
        );
        file.set_len(0)
            .and_then(|()| file.seek(SeekFrom::Start(0)))
            .and_then(|_| file.write_all(record.as_bytes()))
            .map_err(fail)?;
        Ok(register(&mut held, canonical, file, true))
    }

    /// Takes `folder` for reading: refuses a folder another process is writing. A folder
    /// without a lock file (never written by a mit-star that locks, or read-only) is read
    /// without a lock.
    ///
    /// # Errors
    /// [`HarnessError::FolderLocked`] naming the writer; [`HarnessError::Io`] if the lock file
    /// exists but cannot be opened or locked.
    pub(crate) fn shared(folder: &Path) -> Result<Option<Self>, HarnessError> {
        let Ok(canonical) = folder.canonicalize() else {
            return Ok(None);
        };
        let mut held = HELD
            .lock()
            .unwrap_or_else(std::sync::PoisonError::into_inner);
        if let Some(lock) = find(&mut held, &canonical) {
            return Ok(Some(lock));
        }
        let path = canonical.join(LOCK_FILE);
        let file = match File::open(&path) {
            Ok(file) => file,
            Err(e) if e.kind() == std::io::ErrorKind::NotFound => return Ok(None),
            Err(source) => return Err(HarnessError::Io { path, source }),
        };
        match FileExt::try_lock_shared(&file) {
            Ok(()) => Ok(Some(register(&mut held, canonical, file, false))),
            Err(TryLockError::Error(source)) => Err(HarnessError::Io { path, source }),
            Err(TryLockError::WouldBlock) => {
                let (pid, holder) =
                    writer(&path)?.unwrap_or_else(|| (None, "another mit-star process".into()));
                Err(HarnessError::FolderLocked {
                    path: folder.to_path_buf(),
                    pid,
                    holder,
                    advice: "its files change until that process exits; read it when it has \
                             finished"
                        .into(),
                })
            }
        }
    }
}

/// A live lock of `canonical` held by this process (dropping dead entries).
fn find(held: &mut Vec<(PathBuf, Weak<Held>)>, canonical: &Path) -> Option<FolderLock> {
    held.retain(|(_, w)| w.strong_count() > 0);
    held.iter()
        .filter(|(folder, _)| folder == canonical)
        .find_map(|(_, w)| w.upgrade())
        .map(FolderLock)
}

/// Records a lock this process now holds.
fn register(
    held: &mut Vec<(PathBuf, Weak<Held>)>,
    folder: PathBuf,
    file: File,
    exclusive: bool,
) -> FolderLock {
    let lock = Arc::new(Held { file, exclusive });
    held.push((folder, Arc::downgrade(&lock)));
    FolderLock(lock)
}

/// Who writes the folder whose lock file is `path`, if a writer holds it (`None` if only
/// readers do): its process id and "mit-star process 1234 (`mit-star bench … on host`), which
/// is writing it", as it recorded itself.
fn writer(path: &Path) -> Result<Option<(Option<u32>, String)>, HarnessError> {
    let io = |source| HarnessError::Io {
        path: path.to_path_buf(),
        source,
    };
    let mut probe = File::open(path).map_err(io)?;
    match FileExt::try_lock_shared(&probe) {
        // Only readers hold it (or nobody, since): no writer.
        Ok(()) => return Ok(None),
        Err(TryLockError::Error(source)) => return Err(io(source)),
        Err(TryLockError::WouldBlock) => {}
    }
    let mut text = String::new();
    let _ = probe.read_to_string(&mut text);
    let mut lines = text.lines();
    let pid = lines.next().and_then(|l| l.trim().parse::<u32>().ok());
    let command = lines.next().unwrap_or_default().trim();
    let who = match pid {
        Some(pid) if !command.is_empty() => format!("mit-star process {pid} (`{command}`)"),
        Some(pid) => format!("mit-star process {pid}"),
        None => "another mit-star process".into(),
    };
    Ok(Some((pid, format!("{who}, which is writing it"))))
}

/// This process's command line, shortened for a message.
fn command_line() -> String {
    let mut words: Vec<String> = std::env::args().collect();
    if let Some(program) = words.first_mut()
        && let Some(name) = Path::new(program.as_str()).file_name()
    {
        *program = name.to_string_lossy().into_owned();
    }
    let line = words.join(" ").replace(['\n', '\r'], " ");
    match line.char_indices().nth(200) {
        Some((at, _)) => format!("{}…", &line[..at]),
        None => line,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn scratch(name: &str) -> PathBuf {
        let dir = std::env::temp_dir().join(format!("mit-star-lock-{name}-{}", std::process::id()));
        let _ = std::fs::remove_dir_all(&dir);
        std::fs::create_dir_all(&dir).unwrap();
        dir
    }

    #[test]
    fn one_process_shares_its_lock_and_releases_it_with_the_last_holder() {
        let dir = scratch("share");
        assert!(
            FolderLock::shared(&dir).unwrap().is_none(),
            "no lock file yet"
        );
        let mine = FolderLock::exclusive(&dir).unwrap();
        let text = std::fs::read_to_string(dir.join(LOCK_FILE)).unwrap();
        assert_eq!(
            text.lines().next(),
            Some(std::process::id().to_string().as_str())
        );
        let again = FolderLock::exclusive(&dir).unwrap();
        let reader = FolderLock::shared(&dir).unwrap().unwrap();
        assert!(Arc::ptr_eq(&again.0, &mine.0) && Arc::ptr_eq(&reader.0, &mine.0));
        let canonical = dir.canonicalize().unwrap();
        assert!(HELD.lock().unwrap().iter().any(|(folder, held)| {
            *folder == canonical && held.upgrade().is_some_and(|h| Arc::ptr_eq(&h, &mine.0))
        }));
        // Another open file description is another holder, as another process would be.
        let other = File::open(dir.join(LOCK_FILE)).unwrap();
        assert!(matches!(
            FileExt::try_lock_shared(&other),
            Err(TryLockError::WouldBlock)
        ));
        let (pid, holder) = writer(&dir.join(LOCK_FILE)).unwrap().unwrap();
        assert_eq!(pid, Some(std::process::id()));
        assert!(
            holder.starts_with(&format!("mit-star process {} (`", std::process::id())),
            "{holder}"
        );
        drop((mine, again, reader));
        assert!(
            FileExt::try_lock(&other).is_ok(),
            "released with the last clone"
        );
        assert_eq!(std::fs::read_to_string(dir.join(LOCK_FILE)).unwrap(), "");
        drop(other);
        assert!(writer(&dir.join(LOCK_FILE)).unwrap().is_none());
        let _ = std::fs::remove_dir_all(&dir);
    }

    #[test]
    fn a_folder_read_here_is_not_written_here() {
        let dir = scratch("read");
        drop(FolderLock::exclusive(&dir).unwrap());
        let reader = FolderLock::shared(&dir).unwrap().unwrap();
        let message = FolderLock::exclusive(&dir).unwrap_err().to_string();
        assert!(
            message.contains("this process, which is reading it"),
            "{message}"
        );
        drop(reader);
        assert!(FolderLock::exclusive(&dir).is_ok());
        let _ = std::fs::remove_dir_all(&dir);
    }
}
