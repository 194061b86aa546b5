//! [`Shard`]: one of `N` disjoint parts of an experiment's runs, for campaigns spread over
//! several machines (`bench --shard K/N`, then `merge`).

use std::path::Path;
use std::str::FromStr;

use crate::error::HarnessError;

/// The name of the file recording a results folder's shard.
pub const SHARD_FILE: &str = "shard.toml";

/// The `K`-th of `N` parts of an experiment's runs (`1 ≤ K ≤ N`).
///
/// The runs are dealt out round-robin in schedule order ([`RunJob::schedule`](crate::RunJob)):
/// the job at position `p` belongs to part `p mod N + 1`. Every part therefore gets a share
/// of every problem instance and planner (and so of the budget), and every run keeps the seed
/// it has in the whole experiment: the parts together are exactly the experiment.
///
/// ```
/// use mit_star_benches::Shard;
/// let shard: Shard = "2/3".parse()?;
/// let mine: Vec<usize> = (0..9).filter(|&p| shard.owns(p)).collect();
/// assert_eq!(mine, [1, 4, 7]);
/// assert!("0/3".parse::<Shard>().is_err() && "4/3".parse::<Shard>().is_err());
/// # Ok::<(), mit_star_benches::HarnessError>(())
/// ```
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub struct Shard {
    index: usize,
    count: usize,
}

impl Shard {
    /// Part `index` (1-based) of `count`.
    ///
    /// # Errors
    /// [`HarnessError::Usage`] unless `1 ≤ index ≤ count`.
    pub fn new(index: usize, count: usize) -> Result<Self, HarnessError> {
        if count == 0 || index == 0 || index > count {
            return Err(HarnessError::Usage(format!(
                "shard {index}/{count}: give K/N with 1 ≤ K ≤ N (e.g. --shard 2/8)"
            )));
        }
        Ok(Self { index, count })
    }

    /// `K`, counting from 1.
    pub fn index(self) -> usize {
        self.index
    }

    /// `N`.
    pub fn count(self) -> usize {
        self.count
    }

    /// The shard owning the job at `position` of the schedule, among `count`.
    pub fn of(position: usize, count: usize) -> usize {
        position % count.max(1) + 1
    }

    /// Whether the job at `position` of the schedule belongs to this shard.
    pub fn owns(self, position: usize) -> bool {
        Self::of(position, self.count) == self.index
    }

    /// The contents of a folder's [`SHARD_FILE`].
    pub fn to_toml(self) -> String {
        format!(
            "# This folder holds part {} of {} of its experiment's runs (`mit-star bench --shard {}/{}`).\n\
             # Combine the parts with `mit-star merge --output FOLDER PART...`.\n\
             index = {}\ncount = {}\n",
            self.index, self.count, self.index, self.count, self.index, self.count
        )
    }

    /// The shard recorded in `folder` (`None` for a folder of a whole experiment).
    ///
    /// # Errors
    /// [`HarnessError::Io`] if the file exists but cannot be read, [`HarnessError::Usage`]
    /// naming the file if it is malformed.
    pub fn read(folder: &Path) -> Result<Option<Self>, HarnessError> {
        let path = folder.join(SHARD_FILE);
        let text = match std::fs::read_to_string(&path) {
            Ok(text) => text,
            Err(e) if e.kind() == std::io::ErrorKind::NotFound => return Ok(None),
            Err(source) => return Err(HarnessError::Io { path, source }),
        };
        let field = |name: &str| {
            text.lines()
                .filter_map(|l| l.split_once('='))
                .find(|(k, _)| k.trim() == name)
                .and_then(|(_, v)| v.trim().parse::<usize>().ok())
                .ok_or_else(|| {
                    HarnessError::Usage(format!(
                        "`{}`: field `{name}` is missing or not a whole number",
                        path.display()
                    ))
                })
        };
        Self::new(field("index")?, field("count")?).map(Some)
    }
}

impl FromStr for Shard {
    type Err = HarnessError;

    fn from_str(text: &str) -> Result<Self, HarnessError> {
        let bad = || {
            HarnessError::Usage(format!(
                "--shard `{text}`: give K/N, the K-th of N parts (1 ≤ K ≤ N), e.g. 2/8"
            ))
        };
        let (k, n) = text.split_once('/').ok_or_else(bad)?;
        let k = k.trim().parse::<usize>().map_err(|_| bad())?;
        let n = n.trim().parse::<usize>().map_err(|_| bad())?;
        Self::new(k, n).map_err(|_| bad())
    }
}

impl std::fmt::Display for Shard {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "{}/{}", self.index, self.count)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_parts_are_disjoint_and_cover_every_position() {
        for count in 1..6 {
            let shards: Vec<Shard> = (1..=count).map(|k| Shard::new(k, count).unwrap()).collect();
            for position in 0..100 {
                let owners = shards.iter().filter(|s| s.owns(position)).count();
                assert_eq!(owners, 1, "position {position} of {count} shards");
            }
        }
    }

    #[test]
    fn parsing_and_the_file_round_trip() {
        for bad in [
            "", "3", "0/2", "3/2", "1/0", "a/b", "-1/2", "1/2/3", "1.5/2",
        ] {
            assert!(bad.parse::<Shard>().is_err(), "{bad}");
        }
        let shard: Shard = " 3 / 4 ".parse().unwrap();
        assert_eq!((shard.index(), shard.count()), (3, 4));
        assert_eq!(shard.to_string(), "3/4");
        let dir = std::env::temp_dir().join(format!("mit-star-shard-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        assert_eq!(Shard::read(&dir).unwrap(), None);
        std::fs::write(dir.join(SHARD_FILE), shard.to_toml()).unwrap();
        assert_eq!(Shard::read(&dir).unwrap(), Some(shard));
        std::fs::write(dir.join(SHARD_FILE), "index = 5\ncount = 4\n").unwrap();
        assert!(Shard::read(&dir).is_err());
        std::fs::write(dir.join(SHARD_FILE), "count = 4\n").unwrap();
        let message = Shard::read(&dir).unwrap_err().to_string();
        assert!(message.contains("index"), "{message}");
        std::fs::remove_dir_all(&dir).unwrap();
    }
}
