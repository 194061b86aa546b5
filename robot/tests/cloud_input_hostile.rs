//! Hostile bytes never make a point cloud reader panic or allocate beyond its caps: valid
//! PLY, PCD and `.npy` files with bytes changed, cut or inserted, and headers with random
//! counts, are read or refused with an error.

use glam::Vec3;
use mit_star_robot::{CloudFormat, PlyEncoding, parse_cloud};
use proptest::prelude::*;

fn cloud() -> Vec<Vec3> {
    (0..40)
        .map(|i| {
            let f = i as f32;
            Vec3::new(f * 0.1, -f, (f * 0.7).sin())
        })
        .collect()
}

/// A valid file of each kind: PLY in three encodings, PCD ascii, binary and compressed
/// (literal LZF runs), `.npy`.
fn valid_files() -> Vec<(CloudFormat, Vec<u8>)> {
    let points = cloud();
    let header = |data: &str| {
        format!(
            "VERSION 0.7\nFIELDS x y z rgb\nSIZE 4 4 4 4\nTYPE F F F U\nCOUNT 1 1 1 1\n\
             WIDTH {n}\nHEIGHT 1\nVIEWPOINT 0 0 0 1 0 0 0\nPOINTS {n}\nDATA {data}\n",
            n = points.len()
        )
        .into_bytes()
    };
    let mut ascii = header("ascii");
    let mut binary = header("binary");
    let mut columns = Vec::new();
    for p in &points {
        ascii.extend(format!("{} {} {} 7\n", p.x, p.y, p.z).bytes());
        for c in p.to_array() {
            binary.extend(c.to_le_bytes());
        }
        binary.extend(7_u32.to_le_bytes());
    }
    for axis in 0..3 {
        for p in &points {
            columns.extend(p[axis].to_le_bytes());
        }
    }
    columns.extend(vec![0_u8; 4 * points.len()]);
    let mut lzf = Vec::new();
    for chunk in columns.chunks(32) {
        lzf.push(chunk.len() as u8 - 1);
        lzf.extend(chunk);
    }
    let mut compressed = header("binary_compressed");
    compressed.extend((lzf.len() as u32).to_le_bytes());
    compressed.extend((columns.len() as u32).to_le_bytes());
    compressed.extend(lzf);
    vec![
        (
            CloudFormat::Ply,
            mit_star_robot::ply_bytes(&points, PlyEncoding::Ascii),
        ),
        (
            CloudFormat::Ply,
            mit_star_robot::ply_bytes(&points, PlyEncoding::BinaryLittleEndian),
        ),
        (
            CloudFormat::Ply,
            mit_star_robot::ply_bytes(&points, PlyEncoding::BinaryBigEndian),
        ),
        (CloudFormat::Pcd, ascii),
        (CloudFormat::Pcd, binary),
        (CloudFormat::Pcd, compressed),
        (CloudFormat::Npy, mit_star_robot::npy_bytes(&points)),
    ]
}

#[derive(Debug, Clone)]
enum Change {
    Set(usize, u8),
    Cut(usize),
    Insert(usize, Vec<u8>),
}

fn change() -> impl Strategy<Value = Change> {
    prop_oneof![
        (any::<usize>(), any::<u8>()).prop_map(|(at, b)| Change::Set(at, b)),
        any::<usize>().prop_map(Change::Cut),
        (any::<usize>(), prop::collection::vec(any::<u8>(), 1..12))
            .prop_map(|(at, bytes)| Change::Insert(at, bytes)),
        // Digits where the counts are: headers that lie.
        (any::<usize>(), prop::sample::select(b"0123456789".to_vec()))
            .prop_map(|(at, b)| Change::Set(at % 200, b)),
    ]
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(2000))]

    #[test]
    fn changed_files_are_read_or_refused(which in 0usize..7, changes in prop::collection::vec(change(), 1..4)) {
        let (format, mut bytes) = valid_files().swap_remove(which);
        for change in changes {
            let n = bytes.len().max(1);
            match change {
                Change::Set(at, b) => {
                    if !bytes.is_empty() {
                        bytes[at % n] = b;
                    }
                }
                Change::Cut(at) => bytes.truncate(at % n),
                Change::Insert(at, extra) => {
                    let at = at % n;
                    bytes.splice(at..at, extra);
                }
            }
        }
        if let Ok(cloud) = parse_cloud(&bytes, format, "hostile") {
            prop_assert!(!cloud.points.is_empty());
            prop_assert!(cloud.points.len() <= mit_star_robot::MAX_CLOUD_POINTS);
            prop_assert!(cloud.points.iter().all(|p| p.is_finite()));
        }
    }

    #[test]
    fn random_bytes_are_refused(format in prop::sample::select(vec![CloudFormat::Ply, CloudFormat::Pcd, CloudFormat::Npy]), bytes in prop::collection::vec(any::<u8>(), 0..200)) {
        let _ = parse_cloud(&bytes, format, "noise");
    }
}

#[test]
fn the_valid_files_are_read() {
    for (format, bytes) in valid_files() {
        let read = parse_cloud(&bytes, format, "valid").unwrap();
        assert_eq!(read.points, cloud(), "{format}");
    }
}
