//! Unit tests of the three readers and the two writers: small files written to a temporary
//! folder, read back through [`read_cloud`], and the bad inputs the issue lists.

use std::path::PathBuf;

use glam::Vec3;

use super::*;

fn write(name: &str, bytes: &[u8]) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("cloud-input-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let path = dir.join(name);
    std::fs::write(&path, bytes).unwrap();
    path
}

fn read(name: &str, bytes: &[u8]) -> Result<InputCloud, CloudInputError> {
    read_cloud(&write(name, bytes))
}

fn sample_points() -> Vec<Vec3> {
    (0..50)
        .map(|i| {
            let f = i as f32;
            Vec3::new((f * 0.37).sin(), 1e-7 * f - 3.0, f * 123.456)
        })
        .collect()
}

#[test]
fn ply_and_npy_round_trip_exactly() {
    let points = sample_points();
    for (i, encoding) in [
        PlyEncoding::Ascii,
        PlyEncoding::BinaryLittleEndian,
        PlyEncoding::BinaryBigEndian,
    ]
    .into_iter()
    .enumerate()
    {
        let path = write(&format!("round{i}.ply"), b"");
        write_ply(&path, &points, encoding).unwrap();
        let cloud = read_cloud(&path).unwrap();
        assert_eq!(cloud.points, points, "{encoding:?}");
        assert_eq!(cloud.dropped_non_finite, 0);
        assert_eq!(
            cloud.origin,
            CloudOrigin::File {
                path: path.clone(),
                format: CloudFormat::Ply
            }
        );
    }
    let path = write("round.NPY", b"");
    write_npy(&path, &points).unwrap();
    assert_eq!(read_cloud(&path).unwrap().points, points);
    // numpy's own header for the same array: data at a multiple of 64 bytes.
    let bytes = npy_bytes(&points);
    assert_eq!((bytes.len() - 50 * 12) % 64, 0);
    assert!(bytes.starts_with(b"\x93NUMPY\x01\x00"));
}

/// Big-endian doubles among other properties, a list in the vertex element, and a face
/// element before and after it.
#[test]
fn binary_ply_skips_other_properties_lists_and_elements() {
    let mut bytes = b"ply\r\nformat binary_big_endian 1.0\r\ncomment from a scanner\r\n\
        element camera 1\r\nproperty list uchar float intrinsics\r\n\
        element vertex 2\r\nproperty uchar red\r\nproperty double x\r\nproperty double y\r\n\
        property list uchar int extra\r\nproperty double z\r\nproperty float confidence\r\n\
        element face 1\r\nproperty list uchar int vertex_indices\r\nend_header\r\n"
        .to_vec();
    bytes.push(2);
    bytes.extend(1.5_f32.to_be_bytes());
    bytes.extend(2.5_f32.to_be_bytes());
    for (i, xyz) in [[1.0_f64, 2.0, 3.0], [-0.25, 0.5, 1e-3]].iter().enumerate() {
        bytes.push(200);
        bytes.extend(xyz[0].to_be_bytes());
        bytes.extend(xyz[1].to_be_bytes());
        bytes.push(i as u8);
        for k in 0..i {
            bytes.extend((k as i32).to_be_bytes());
        }
        bytes.extend(xyz[2].to_be_bytes());
        bytes.extend(0.9_f32.to_be_bytes());
    }
    bytes.push(3);
    for k in [0_i32, 1, 0] {
        bytes.extend(k.to_be_bytes());
    }
    let cloud = read("mixed.ply", &bytes).unwrap();
    assert_eq!(
        cloud.points,
        [Vec3::new(1.0, 2.0, 3.0), Vec3::new(-0.25, 0.5, 1e-3)]
    );
    // One byte fewer: the face list ends early.
    let e = read("mixed_cut.ply", &bytes[..bytes.len() - 1]).unwrap_err();
    assert!(matches!(e, CloudInputError::Truncated { .. }), "{e}");
    assert!(e.to_string().contains("element `face`"), "{e}");
}

#[test]
fn ascii_ply_drops_nan_rows_and_counts_them() {
    let text = "ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\nproperty float y\n\
        property float z\nproperty uchar red\nelement face 1\nproperty list uchar int vertex_indices\n\
        end_header\n0 0 0 255\n1 nan 2 0\n\n3 4 5 1\ninf 0 0 3\n3 0 1 2\n";
    let cloud = read("nan.ply", text.as_bytes()).unwrap();
    assert_eq!(cloud.points, [Vec3::ZERO, Vec3::new(3.0, 4.0, 5.0)]);
    assert_eq!(cloud.dropped_non_finite, 2);
    let all_nan = "ply\nformat ascii 1.0\nelement vertex 2\nproperty float x\nproperty float y\n\
        property float z\nend_header\nnan 0 0\n0 NaN 0\n";
    let e = read("all_nan.ply", all_nan.as_bytes()).unwrap_err();
    assert!(
        matches!(e, CloudInputError::Empty { dropped: 2, .. }),
        "{e}"
    );
    assert!(e.to_string().contains("all_nan.ply"), "{e}");
}

#[test]
fn bad_ply_files_are_named_errors() {
    let header = |format: &str, count: &str| {
        format!(
            "ply\nformat {format} 1.0\nelement vertex {count}\nproperty float x\n\
             property float y\nproperty float z\nend_header\n"
        )
    };
    let e = read("empty.ply", b"").unwrap_err();
    assert!(matches!(e, CloudInputError::Header { .. }), "{e}");
    assert!(e.to_string().contains("empty.ply"), "{e}");
    // Truncated binary: 3 points declared, 2.5 there.
    let mut bytes = header("binary_little_endian", "3").into_bytes();
    bytes.extend(vec![0_u8; 30]);
    let e = read("truncated.ply", &bytes).unwrap_err();
    assert!(
        matches!(e, CloudInputError::Truncated { declared: 3, .. }),
        "{e}"
    );
    assert!(e.to_string().contains("holds 30 bytes"), "{e}");
    // A header count larger than the data, ASCII.
    let text = header("ascii", "5") + "0 0 0\n1 1 1\n";
    let e = read("short.ply", text.as_bytes()).unwrap_err();
    assert!(e.to_string().contains("ends after 2 of the 5 rows"), "{e}");
    // A header count smaller than the data.
    let text = header("ascii", "1") + "0 0 0\n1 1 1\n";
    let e = read("long.ply", text.as_bytes()).unwrap_err();
    assert!(matches!(e, CloudInputError::TrailingData { .. }), "{e}");
    let mut bytes = header("binary_big_endian", "1").into_bytes();
    bytes.extend(vec![0_u8; 13]);
    let e = read("long_binary.ply", &bytes).unwrap_err();
    assert!(e.to_string().contains("1 more bytes"), "{e}");
    // A header count of 10¹²: refused before allocating.
    let mut bytes = header("binary_little_endian", "1000000000000").into_bytes();
    bytes.extend(vec![0_u8; 24]);
    let e = read("huge.ply", &bytes).unwrap_err();
    assert!(
        matches!(
            e,
            CloudInputError::TooManyPoints {
                declared: 1_000_000_000_000,
                ..
            }
        ),
        "{e}"
    );
    // Integer coordinates, a missing axis, an unknown type, no vertex, a bad word.
    let text = "ply\nformat ascii 1.0\nelement vertex 1\nproperty int x\nproperty float y\n\
        property float z\nend_header\n1 2 3\n";
    let e = read("int.ply", text.as_bytes()).unwrap_err();
    assert!(
        matches!(&e, CloudInputError::UnsupportedField { field, .. } if field == "x"),
        "{e}"
    );
    let text = "ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nproperty float y\nend_header\n1 2\n";
    let e = read("xy.ply", text.as_bytes()).unwrap_err();
    assert!(
        matches!(&e, CloudInputError::UnsupportedField { field, .. } if field == "z"),
        "{e}"
    );
    let text = "ply\nformat ascii 1.0\nelement vertex 1\nproperty half x\nend_header\n";
    let e = read("half.ply", text.as_bytes()).unwrap_err();
    assert!(
        e.to_string().contains("unknown property type `half`"),
        "{e}"
    );
    let text = "ply\nformat ascii 1.0\nelement face 0\nend_header\n";
    let e = read("faces.ply", text.as_bytes()).unwrap_err();
    assert!(e.to_string().contains("no `vertex` element"), "{e}");
    let text = header("ascii", "1") + "0 zero 0\n";
    let e = read("word.ply", text.as_bytes()).unwrap_err();
    assert!(
        e.to_string()
            .contains("row 1 of the data: `zero` is not a number"),
        "{e}"
    );
    let text = header("ascii", "1") + "0 0\n";
    let e = read("few.ply", text.as_bytes()).unwrap_err();
    assert!(matches!(e, CloudInputError::Data { .. }), "{e}");
    let e = read("no_end.ply", b"ply\nformat ascii 1.0\n").unwrap_err();
    assert!(e.to_string().contains("no `end_header`"), "{e}");
}

/// A PCD field: name, size, type, count.
type PcdField<'a> = (&'a str, u8, char, usize);

/// The PCD header of `fields` for `points` points.
fn pcd_header(fields: &[PcdField<'_>], points: u64, data: &str) -> String {
    let column =
        |f: &dyn Fn(&PcdField<'_>) -> String| fields.iter().map(f).collect::<Vec<_>>().join(" ");
    format!(
        "# .PCD v0.7 - Point Cloud Data file format\nVERSION 0.7\nFIELDS {}\nSIZE {}\nTYPE {}\n\
         COUNT {}\nWIDTH {points}\nHEIGHT 1\nVIEWPOINT 0 0 0 1 0 0 0\nPOINTS {points}\nDATA {data}\n",
        column(&|f| f.0.to_string()),
        column(&|f| f.1.to_string()),
        column(&|f| f.2.to_string()),
        column(&|f| f.3.to_string()),
    )
}

#[test]
fn pcd_ascii_binary_and_compressed_are_read() {
    let xyzrgb = [
        ("x", 4, 'F', 1),
        ("y", 4, 'F', 1),
        ("z", 4, 'F', 1),
        ("rgb", 4, 'U', 1),
    ];
    let text = pcd_header(&xyzrgb, 3, "ascii") + "1 2 3 4278190080\nnan nan nan 0\n-1.5 0 2e-3 7\n";
    let cloud = read("cloud.pcd", text.as_bytes()).unwrap();
    assert_eq!(
        cloud.points,
        [Vec3::new(1.0, 2.0, 3.0), Vec3::new(-1.5, 0.0, 2e-3)]
    );
    assert_eq!(cloud.dropped_non_finite, 1);
    // Binary: PCL's `_` padding, double coordinates, a field with a count.
    let fields = [
        ("_", 1, 'U', 4),
        ("x", 8, 'F', 1),
        ("y", 8, 'F', 1),
        ("z", 8, 'F', 1),
        ("normal", 4, 'F', 3),
    ];
    let points = [[0.5_f64, -1.0, 2.0], [3.0, 4.0, 5.0]];
    let mut bytes = pcd_header(&fields, 2, "binary").into_bytes();
    for p in points {
        bytes.extend([0_u8; 4]);
        for c in p {
            bytes.extend(c.to_le_bytes());
        }
        bytes.extend([0_u8; 12]);
    }
    let cloud = read("binary.pcd", &bytes).unwrap();
    assert_eq!(
        cloud.points,
        [Vec3::new(0.5, -1.0, 2.0), Vec3::new(3.0, 4.0, 5.0)]
    );
    let e = read("binary_cut.pcd", &bytes[..bytes.len() - 3]).unwrap_err();
    assert!(
        matches!(e, CloudInputError::Truncated { declared: 2, .. }),
        "{e}"
    );
    // binary_compressed: columns (every x, every y, every z, every intensity), LZF literals.
    let fields = [
        ("x", 4, 'F', 1),
        ("y", 4, 'F', 1),
        ("z", 4, 'F', 1),
        ("intensity", 1, 'U', 1),
    ];
    let points = sample_points();
    let mut plain = Vec::new();
    for axis in 0..3 {
        for p in &points {
            plain.extend(p[axis].to_le_bytes());
        }
    }
    plain.extend(vec![9_u8; points.len()]);
    let mut compressed = Vec::new();
    for chunk in plain.chunks(32) {
        compressed.push(chunk.len() as u8 - 1);
        compressed.extend(chunk);
    }
    let mut bytes = pcd_header(&fields, points.len() as u64, "binary_compressed").into_bytes();
    bytes.extend((compressed.len() as u32).to_le_bytes());
    bytes.extend((plain.len() as u32).to_le_bytes());
    bytes.extend(&compressed);
    assert_eq!(read("compressed.pcd", &bytes).unwrap().points, points);
    // A block that claims another size than the header's points need.
    let at = bytes.len() - compressed.len() - 4;
    bytes[at..at + 4].copy_from_slice(&((plain.len() + 1) as u32).to_le_bytes());
    let e = read("compressed_bad.pcd", &bytes).unwrap_err();
    assert!(matches!(e, CloudInputError::Data { .. }), "{e}");
}

#[test]
fn bad_pcd_files_are_named_errors() {
    let xyz = [("x", 4, 'F', 1), ("y", 4, 'F', 1), ("z", 4, 'F', 1)];
    // An unknown field type.
    let text = pcd_header(
        &[
            ("x", 4, 'F', 1),
            ("y", 4, 'F', 1),
            ("z", 4, 'F', 1),
            ("label", 4, 'X', 1),
        ],
        1,
        "ascii",
    ) + "0 0 0 1\n";
    let e = read("type.pcd", text.as_bytes()).unwrap_err();
    assert!(
        matches!(&e, CloudInputError::UnsupportedField { field, .. } if field == "label"),
        "{e}"
    );
    assert!(e.to_string().contains("type.pcd"), "{e}");
    let text = pcd_header(
        &[("x", 2, 'F', 1), ("y", 4, 'F', 1), ("z", 4, 'F', 1)],
        1,
        "ascii",
    ) + "0 0 0\n";
    let e = read("half.pcd", text.as_bytes()).unwrap_err();
    assert!(matches!(e, CloudInputError::UnsupportedField { .. }), "{e}");
    let text = pcd_header(
        &[("x", 4, 'F', 2), ("y", 4, 'F', 1), ("z", 4, 'F', 1)],
        1,
        "ascii",
    ) + "0 0 0 0\n";
    let e = read("count.pcd", text.as_bytes()).unwrap_err();
    assert!(
        matches!(&e, CloudInputError::UnsupportedField { field, .. } if field == "x"),
        "{e}"
    );
    // 10¹² points, an ASCII count larger and smaller than the rows.
    let mut bytes = pcd_header(&xyz, 1_000_000_000_000, "binary").into_bytes();
    bytes.extend([0_u8; 12]);
    let e = read("huge.pcd", &bytes).unwrap_err();
    assert!(matches!(e, CloudInputError::TooManyPoints { .. }), "{e}");
    let e = read(
        "short.pcd",
        (pcd_header(&xyz, 3, "ascii") + "0 0 0\n").as_bytes(),
    )
    .unwrap_err();
    assert!(e.to_string().contains("ends after 1 rows"), "{e}");
    let e = read(
        "long.pcd",
        (pcd_header(&xyz, 1, "ascii") + "0 0 0\n1 1 1\n").as_bytes(),
    )
    .unwrap_err();
    assert!(matches!(e, CloudInputError::TrailingData { .. }), "{e}");
    let e = read(
        "wide.pcd",
        (pcd_header(&xyz, 1, "ascii") + "0 0 0 0\n").as_bytes(),
    )
    .unwrap_err();
    assert!(
        e.to_string().contains("4 values where the fields give 3"),
        "{e}"
    );
    let e = read("nodata.pcd", b"VERSION 0.7\nFIELDS x y z\n").unwrap_err();
    assert!(e.to_string().contains("no `DATA` line"), "{e}");
    let e = read("weird.pcd", b"VERSION 0.7\nCOLOUR red\n").unwrap_err();
    assert!(
        e.to_string().contains("unknown header entry `COLOUR`"),
        "{e}"
    );
    let e = read("empty.pcd", pcd_header(&xyz, 0, "binary").as_bytes()).unwrap_err();
    assert!(
        matches!(e, CloudInputError::Empty { dropped: 0, .. }),
        "{e}"
    );
}

/// A `.npy` file with this header dictionary and data.
fn npy(version: u8, dict: &str, data: &[u8]) -> Vec<u8> {
    let mut bytes = b"\x93NUMPY".to_vec();
    bytes.extend([version, 0]);
    if version == 1 {
        bytes.extend((dict.len() as u16).to_le_bytes());
    } else {
        bytes.extend((dict.len() as u32).to_le_bytes());
    }
    bytes.extend(dict.as_bytes());
    bytes.extend(data);
    bytes
}

#[test]
fn npy_orders_types_and_versions() {
    // Fortran order, float64: the columns one after another.
    let mut data = Vec::new();
    for v in [1.0_f64, 4.0, 2.0, 5.0, 3.0, f64::NAN] {
        data.extend(v.to_le_bytes());
    }
    let dict = "{'descr': '<f8', 'fortran_order': True, 'shape': (2, 3), }\n";
    let cloud = read("fortran.npy", &npy(1, dict, &data)).unwrap();
    assert_eq!(cloud.points, [Vec3::new(1.0, 2.0, 3.0)]);
    assert_eq!(cloud.dropped_non_finite, 1);
    // Big-endian float32, version 2.
    let mut data = Vec::new();
    for v in [0.5_f32, -0.5, 8.0] {
        data.extend(v.to_be_bytes());
    }
    let dict = "{\"descr\": \">f4\", \"fortran_order\": False, \"shape\": (1,3)}";
    assert_eq!(
        read("big.npy", &npy(2, dict, &data)).unwrap().points,
        [Vec3::new(0.5, -0.5, 8.0)]
    );
}

#[test]
fn bad_npy_files_are_named_errors() {
    let dict = |descr: &str, shape: &str| {
        format!("{{'descr': '{descr}', 'fortran_order': False, 'shape': {shape}, }}")
    };
    let e = read("shape.npy", &npy(1, &dict("<f4", "(4, 2)"), &[0; 32])).unwrap_err();
    assert!(
        matches!(&e, CloudInputError::UnsupportedField { field, .. } if field == "shape"),
        "{e}"
    );
    let e = read("int.npy", &npy(1, &dict("<i4", "(1, 3)"), &[0; 12])).unwrap_err();
    assert!(
        matches!(&e, CloudInputError::UnsupportedField { field, .. } if field == "descr"),
        "{e}"
    );
    let e = read(
        "huge.npy",
        &npy(1, &dict("<f4", "(1000000000000, 3)"), &[0; 12]),
    )
    .unwrap_err();
    assert!(matches!(e, CloudInputError::TooManyPoints { .. }), "{e}");
    let e = read("cut.npy", &npy(1, &dict("<f4", "(2, 3)"), &[0; 20])).unwrap_err();
    assert!(
        matches!(e, CloudInputError::Truncated { declared: 2, .. }),
        "{e}"
    );
    let e = read("long.npy", &npy(1, &dict("<f4", "(1, 3)"), &[0; 16])).unwrap_err();
    assert!(matches!(e, CloudInputError::TrailingData { .. }), "{e}");
    let e = read("empty.npy", b"").unwrap_err();
    assert!(matches!(e, CloudInputError::Header { .. }), "{e}");
    let e = read("none.npy", &npy(1, &dict("<f4", "(0, 3)"), &[])).unwrap_err();
    assert!(matches!(e, CloudInputError::Empty { .. }), "{e}");
    let e = read("header.npy", &npy(1, "{'descr': '<f4'", &[])).unwrap_err();
    assert!(matches!(e, CloudInputError::Header { .. }), "{e}");
}

#[test]
fn files_are_read_bounded_and_by_extension() {
    let e = read("cloud.xyz", b"0 0 0\n").unwrap_err();
    assert!(
        matches!(&e, CloudInputError::UnknownFormat { extension, .. } if extension == "xyz"),
        "{e}"
    );
    let dir = std::env::temp_dir()
        .join(format!("cloud-input-{}", std::process::id()))
        .join("folder.ply");
    std::fs::create_dir_all(&dir).unwrap();
    let e = read_cloud(&dir).unwrap_err();
    assert!(e.to_string().contains("not a regular file"), "{e}");
    let e = read_cloud(&dir.with_file_name("missing.pcd")).unwrap_err();
    assert!(matches!(e, CloudInputError::Io { .. }), "{e}");
    // Bytes from elsewhere are named by the caller.
    let e = parse_cloud(b"", CloudFormat::Ply, "camera frame 12").unwrap_err();
    assert!(e.to_string().starts_with("camera frame 12:"), "{e}");
}

#[test]
fn arrays_in_memory_follow_the_readers_rules() {
    let cloud =
        InputCloud::from_xyz("driver", &[1.0_f64, 2.0, 3.0, 4.0, f64::INFINITY, 6.0]).unwrap();
    assert_eq!(cloud.points, [Vec3::new(1.0, 2.0, 3.0)]);
    assert_eq!(cloud.dropped_non_finite, 1);
    assert_eq!(cloud.origin.to_string(), "array `driver`");
    let e = InputCloud::from_xyz("dark", &[f32::NAN; 6]).unwrap_err();
    assert_eq!(
        e.to_string(),
        "dark: the point cloud is empty (2 points with NaN or infinite coordinates dropped)"
    );
    let e = InputCloud::from_xyz::<f32>("nothing", &[]).unwrap_err();
    assert!(
        matches!(e, CloudInputError::Empty { dropped: 0, .. }),
        "{e}"
    );
    // An f64 beyond f32's range is infinite in f32: dropped.
    let cloud = InputCloud::from_xyz("far", &[1e39_f64, 0.0, 0.0, 0.0, 0.0, 0.0]).unwrap();
    assert_eq!((cloud.len(), cloud.dropped_non_finite), (1, 1));
}
