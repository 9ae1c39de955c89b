//! The checkpoint file format: a JSON header (the small state, readable with `head -c`) followed by named
//! arrays of f64 stored as raw little-endian bytes, so that a restart gets back every bit of the particles.
//!
//! Layout: the line `bowwave checkpoint 1\n`; the header's length in bytes (u64 LE) and the header (UTF-8
//! JSON); the number of arrays (u64 LE); per array its name's length (u64 LE), the name, its length in
//! values (u64 LE) and the values (f64 LE). Written atomically ([`write_atomic`]).

use super::atomic::write_atomic;
use std::collections::BTreeMap;
use std::path::Path;

const MAGIC: &[u8] = b"bowwave checkpoint 1\n";

/// The contents of a checkpoint file.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Checkpoint {
    pub header: serde_json::Value,
    pub arrays: BTreeMap<String, Vec<f64>>,
}

impl Checkpoint {
    /// Writes the file atomically: a crash while writing leaves the previous checkpoint in place.
    pub fn write(&self, path: &Path) -> anyhow::Result<()> {
        let header = serde_json::to_vec(&self.header)?;
        let values: usize = self.arrays.values().map(Vec::len).sum();
        let mut bytes = Vec::with_capacity(MAGIC.len() + header.len() + 8 * values + 64 * self.arrays.len());
        bytes.extend_from_slice(MAGIC);
        bytes.extend_from_slice(&(header.len() as u64).to_le_bytes());
        bytes.extend_from_slice(&header);
        bytes.extend_from_slice(&(self.arrays.len() as u64).to_le_bytes());
        for (name, v) in &self.arrays {
            bytes.extend_from_slice(&(name.len() as u64).to_le_bytes());
            bytes.extend_from_slice(name.as_bytes());
            bytes.extend_from_slice(&(v.len() as u64).to_le_bytes());
            for x in v {
                bytes.extend_from_slice(&x.to_le_bytes());
            }
        }
        write_atomic(path, &bytes).map_err(|e| anyhow::anyhow!("cannot write checkpoint {}: {e}", path.display()))
    }

    /// Reads a file written by [`Checkpoint::write`]; a foreign or truncated file is an error naming it.
    pub fn read(path: &Path) -> anyhow::Result<Checkpoint> {
        let bytes =
            std::fs::read(path).map_err(|e| anyhow::anyhow!("cannot read checkpoint {}: {e}", path.display()))?;
        let bad = |what: &str| anyhow::anyhow!("checkpoint {}: {what}", path.display());
        let rest = bytes
            .strip_prefix(MAGIC)
            .ok_or_else(|| bad("not a bowwave checkpoint (expected the first line `bowwave checkpoint 1`)"))?;
        let mut r = Reader { rest };
        let n = r.len(&bad)?;
        let header = serde_json::from_slice(r.take(n, &bad)?).map_err(|e| bad(&format!("header: {e}")))?;
        let count = r.len(&bad)?;
        let mut arrays = BTreeMap::new();
        for _ in 0..count {
            let n = r.len(&bad)?;
            let name = String::from_utf8(r.take(n, &bad)?.to_vec()).map_err(|_| bad("an array name is not UTF-8"))?;
            let n = r.len(&bad)?;
            let raw = r.take(n.checked_mul(8).ok_or_else(|| bad("array too long"))?, &bad)?;
            let v = raw
                .chunks_exact(8)
                .map(|c| f64::from_le_bytes(c.try_into().expect("8 bytes")))
                .collect();
            arrays.insert(name, v);
        }
        if !r.rest.is_empty() {
            return Err(bad("bytes after the last array"));
        }
        Ok(Checkpoint { header, arrays })
    }

    /// Reads only the JSON header (the small state), not the arrays: for a look at a run in progress
    /// (`bowwave study --status`) without loading its particles. Errors name the file, as [`Checkpoint::read`].
    pub fn read_header(path: &Path) -> anyhow::Result<serde_json::Value> {
        use std::io::Read;
        let bad = |what: &str| anyhow::anyhow!("checkpoint {}: {what}", path.display());
        let mut f =
            std::fs::File::open(path).map_err(|e| anyhow::anyhow!("cannot read checkpoint {}: {e}", path.display()))?;
        let mut magic = Vec::new();
        (&mut f)
            .take(MAGIC.len() as u64)
            .read_to_end(&mut magic)
            .map_err(|e| bad(&e.to_string()))?;
        if magic != MAGIC {
            return Err(bad(
                "not a bowwave checkpoint (expected the first line `bowwave checkpoint 1`)",
            ));
        }
        let mut len = [0u8; 8];
        f.read_exact(&mut len).map_err(|_| bad("truncated"))?;
        let n = usize::try_from(u64::from_le_bytes(len)).map_err(|_| bad("length too large"))?;
        let mut header = Vec::new();
        f.take(n as u64)
            .read_to_end(&mut header)
            .map_err(|e| bad(&format!("header: {e}")))?;
        if header.len() != n {
            return Err(bad("truncated"));
        }
        serde_json::from_slice(&header).map_err(|e| bad(&format!("header: {e}")))
    }

    /// An array by name, with an error naming the file when it is missing or not `len` long.
    pub fn array(&self, path: &Path, name: &str, len: Option<usize>) -> anyhow::Result<&[f64]> {
        let v = self
            .arrays
            .get(name)
            .ok_or_else(|| anyhow::anyhow!("checkpoint {}: no array `{name}`", path.display()))?;
        match len {
            Some(n) if v.len() != n => Err(anyhow::anyhow!(
                "checkpoint {}: array `{name}` holds {} values, expected {n}",
                path.display(),
                v.len()
            )),
            _ => Ok(v),
        }
    }
}

struct Reader<'a> {
    rest: &'a [u8],
}

impl<'a> Reader<'a> {
    fn take(&mut self, n: usize, bad: &dyn Fn(&str) -> anyhow::Error) -> anyhow::Result<&'a [u8]> {
        if self.rest.len() < n {
            return Err(bad("truncated"));
        }
        let (a, b) = self.rest.split_at(n);
        self.rest = b;
        Ok(a)
    }

    fn len(&mut self, bad: &dyn Fn(&str) -> anyhow::Error) -> anyhow::Result<usize> {
        let b = self.take(8, bad)?;
        usize::try_from(u64::from_le_bytes(b.try_into().expect("8 bytes"))).map_err(|_| bad("length too large"))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn round_trip_keeps_every_bit_and_truncation_is_an_error() {
        let dir = std::env::temp_dir().join(format!("bowwave-ckpt-{}", std::process::id()));
        let path = dir.join("c.bin");
        let mut c = Checkpoint {
            header: serde_json::json!({"time": 0.1, "name": "x"}),
            ..Default::default()
        };
        c.arrays.insert(
            "a".into(),
            vec![0.1 + 0.2, f64::NAN.copysign(-1.0), -0.0, 1e-300, f64::INFINITY],
        );
        c.arrays.insert("empty".into(), vec![]);
        c.write(&path).unwrap();
        let back = Checkpoint::read(&path).unwrap();
        assert_eq!(back.header, c.header);
        assert_eq!(Checkpoint::read_header(&path).unwrap(), c.header);
        let bits = |v: &[f64]| v.iter().map(|x| x.to_bits()).collect::<Vec<_>>();
        assert_eq!(bits(&back.arrays["a"]), bits(&c.arrays["a"]));
        assert!(back.arrays["empty"].is_empty());
        let bytes = std::fs::read(&path).unwrap();
        std::fs::write(&path, &bytes[..bytes.len() - 3]).unwrap();
        let e = format!("{:#}", Checkpoint::read(&path).unwrap_err());
        assert!(e.contains("c.bin") && e.contains("truncated"), "{e}");
        std::fs::write(&path, &bytes[..MAGIC.len() + 8 + 5]).unwrap();
        let e = format!("{:#}", Checkpoint::read_header(&path).unwrap_err());
        assert!(e.contains("c.bin") && e.contains("truncated"), "{e}");
        std::fs::write(&path, b"hello").unwrap();
        let e = format!("{:#}", Checkpoint::read(&path).unwrap_err());
        assert!(e.contains("not a bowwave checkpoint"), "{e}");
        let e = format!("{:#}", Checkpoint::read_header(&path).unwrap_err());
        assert!(e.contains("not a bowwave checkpoint"), "{e}");
        std::fs::remove_dir_all(&dir).ok();
    }
}
