//! Splitting a batch into N disjoint shards (`--shard K/N`), so that CI jobs can check one
//! large tree in parallel and merge their reports (`x3dcheck merge`).
//!
//! A file's shard depends on its own path only, so adding or removing a file moves no
//! other file, and every machine and run agrees:
//!
//! - the key is the path relative to the directory argument the file was found under, or
//!   the path as given for a file named on the command line; its components are joined by
//!   `/` (`\` counts as a separator too), `.` components left out;
//! - the shard is H mod N + 1, where H is the first 8 bytes, big-endian, of the SHA-256 of
//!   the key as UTF-8 (the first 16 hex digits of `printf %s sub/a.x3d | sha256sum`).
//!   `python3 -c 'import hashlib, sys; print(int(hashlib.sha256(sys.argv[1].encode()).hexdigest()[:16], 16) % 3 + 1)' sub/a.x3d`
//!   prints the shard of `DIR/sub/a.x3d` in a split in 3. A checksum such as CRC-32 would
//!   be cheaper but is linear: files whose names differ in one digit (`part1.x3d` …
//!   `part8.x3d`) then all fall in one shard of 2 or 4;
//! - stdin (`-`) is in shard 1.

use std::fmt;
use std::path::{Component, Path};
use std::str::FromStr;

use serde::{Deserialize, Serialize};
use sha2::{Digest, Sha256};

/// Shard `index` of `count`, 1 ≤ index ≤ count.
#[derive(Copy, Clone, Debug, PartialEq, Eq, Serialize, Deserialize)]
pub struct Shard {
    pub index: u32,
    pub count: u32,
}

impl Shard {
    pub fn new(index: u32, count: u32) -> Result<Shard, String> {
        if (1..=count).contains(&index) {
            Ok(Shard { index, count })
        } else {
            Err(format!("shard {index}/{count}: K/N needs 1 ≤ K ≤ N"))
        }
    }

    /// Whether the file with this path (relative to its directory argument, or as given)
    /// is in this shard.
    pub fn holds(self, path: &Path) -> bool {
        hash(&key(path)) % u64::from(self.count) + 1 == u64::from(self.index)
    }

    pub fn holds_stdin(self) -> bool {
        self.index == 1
    }
}

impl FromStr for Shard {
    type Err = String;

    fn from_str(text: &str) -> Result<Shard, String> {
        let number = |part: &str| part.trim().parse::<u32>().ok();
        let parsed = text
            .split_once('/')
            .and_then(|(k, n)| Some((number(k)?, number(n)?)));
        match parsed {
            Some((index, count)) => Shard::new(index, count),
            None => Err(format!("`{text}` is not K/N (e.g. 2/4)")),
        }
    }
}

impl fmt::Display for Shard {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{}/{}", self.index, self.count)
    }
}

fn hash(key: &str) -> u64 {
    let digest = Sha256::digest(key.as_bytes());
    let mut first = [0; 8];
    first.copy_from_slice(&digest[..8]);
    u64::from_be_bytes(first)
}

/// The machine-independent form of a path that picks its shard.
fn key(path: &Path) -> String {
    let parts: Vec<String> = path
        .components()
        .filter(|c| *c != Component::CurDir)
        .map(|c| match c {
            Component::RootDir => String::new(),
            c => c.as_os_str().to_string_lossy().into_owned(),
        })
        .collect();
    // A lone root gives [""]: keep its slash.
    match parts.as_slice() {
        [only] if only.is_empty() => "/".to_string(),
        _ => parts.join("/").replace('\\', "/"),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn keys_are_normalized() {
        assert_eq!(key(Path::new("a.x3d")), "a.x3d");
        assert_eq!(key(Path::new("./sub//a.x3d")), "sub/a.x3d");
        assert_eq!(key(Path::new("sub/./a.x3d")), "sub/a.x3d");
        assert_eq!(key(Path::new("sub\\a.x3d")), "sub/a.x3d");
        assert_eq!(key(Path::new("../x/a.x3d")), "../x/a.x3d");
        assert_eq!(key(Path::new("/abs/a.x3d")), "/abs/a.x3d");
    }

    /// The rule is a contract with the users' CI scripts: these numbers come from Python's
    /// hashlib (see the module doc).
    #[test]
    fn shards_are_sha256_of_the_key() {
        let shard_of = |path: &str, count| {
            (1..=count)
                .find(|&index| Shard { index, count }.holds(Path::new(path)))
                .unwrap()
        };
        assert_eq!(hash("sub/a.x3d"), 0xc853_5b87_6a7c_cb32);
        assert_eq!(shard_of("sub/a.x3d", 3), 3);
        assert_eq!(shard_of("./sub\\a.x3d", 3), shard_of("sub/a.x3d", 3));
        assert_eq!(shard_of("scene.x3d", 1), 1);
        let spread: Vec<u32> = (0..8).map(|i| shard_of(&format!("s{i}.x3d"), 4)).collect();
        assert_eq!(spread, [4, 1, 3, 2, 2, 3, 3, 4]);
    }

    #[test]
    fn parses_k_of_n() {
        assert_eq!("2/3".parse(), Ok(Shard { index: 2, count: 3 }));
        assert_eq!("1/1".parse::<Shard>().unwrap().to_string(), "1/1");
        for bad in ["0/3", "4/3", "1/0", "3", "a/b", "1/2/3", "-1/2", ""] {
            assert!(bad.parse::<Shard>().is_err(), "{bad}");
        }
        assert!(Shard::new(1, 2).unwrap().holds_stdin());
        assert!(!Shard::new(2, 2).unwrap().holds_stdin());
    }
}
