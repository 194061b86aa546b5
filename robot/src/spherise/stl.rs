//! Reading STL files, binary and ASCII, into a [`TriangleMesh`].

use std::path::Path;

use glam::DVec3;

use super::spherise_error::SpheriseError;
use super::triangle_mesh::TriangleMesh;

/// The most triangles an STL may hold (a 500 MB binary file): larger counts are refused
/// before any allocation.
const MAX_TRIANGLES: usize = 10_000_000;

/// Reads an STL file (binary or ASCII) into a mesh with shared vertices.
///
/// # Errors
/// [`SpheriseError::Io`] if the file cannot be read, [`SpheriseError::Stl`] if it is neither
/// a well-formed binary nor ASCII STL, [`SpheriseError::BadMesh`] if it has no triangle or a
/// coordinate that is not finite.
pub fn read_stl(path: &Path) -> Result<TriangleMesh, SpheriseError> {
    let bytes = std::fs::read(path).map_err(|source| SpheriseError::Io {
        path: path.to_owned(),
        source,
    })?;
    parse_stl(&bytes).map_err(|message| SpheriseError::Stl {
        path: path.to_owned(),
        message,
    })
}

/// Parses the bytes of an STL file: binary when the size is exactly that announced by the
/// header's triangle count (some binary files begin with `solid` too), ASCII otherwise.
///
/// # Errors
/// A message naming what is wrong.
pub fn parse_stl(bytes: &[u8]) -> Result<TriangleMesh, String> {
    let soup = if is_binary(bytes) {
        binary_triangles(bytes)?
    } else {
        let text = std::str::from_utf8(bytes)
            .map_err(|_| "neither a binary STL (size and count disagree) nor ASCII text")?;
        ascii_triangles(text)?
    };
    TriangleMesh::from_soup(&soup).map_err(|e| e.to_string())
}

fn is_binary(bytes: &[u8]) -> bool {
    bytes.len() >= 84 && {
        let count = u32::from_le_bytes([bytes[80], bytes[81], bytes[82], bytes[83]]) as usize;
        count
            .checked_mul(50)
            .and_then(|n| n.checked_add(84))
            .is_some_and(|n| n == bytes.len())
    }
}

fn binary_triangles(bytes: &[u8]) -> Result<Vec<[DVec3; 3]>, String> {
    let count = (bytes.len() - 84) / 50;
    if count > MAX_TRIANGLES {
        return Err(format!("{count} triangles (at most {MAX_TRIANGLES})"));
    }
    let float = |at: usize| {
        f64::from(f32::from_le_bytes([
            bytes[at],
            bytes[at + 1],
            bytes[at + 2],
            bytes[at + 3],
        ]))
    };
    let mut soup = Vec::with_capacity(count);
    for t in 0..count {
        // 12 bytes of normal, then three vertices of three f32 each, then 2 attribute bytes.
        let base = 84 + 50 * t + 12;
        let vertex = |v: usize| {
            let at = base + 12 * v;
            DVec3::new(float(at), float(at + 4), float(at + 8))
        };
        soup.push([vertex(0), vertex(1), vertex(2)]);
    }
    Ok(soup)
}

fn ascii_triangles(text: &str) -> Result<Vec<[DVec3; 3]>, String> {
    let mut words = text.split_whitespace();
    if words.next() != Some("solid") {
        return Err("neither a binary STL (size and count disagree) nor ASCII (`solid …`)".into());
    }
    let mut soup = Vec::new();
    let mut corners = Vec::with_capacity(3);
    let mut line = 0_usize;
    let mut inside_loop = false;
    while let Some(word) = words.next() {
        match word {
            "vertex" => {
                if !inside_loop {
                    return Err(format!(
                        "`vertex` outside `outer loop` (triangle {})",
                        soup.len() + 1
                    ));
                }
                let mut xyz = [0.0; 3];
                for value in &mut xyz {
                    let w = words
                        .next()
                        .ok_or("a vertex with fewer than 3 coordinates")?;
                    *value = w
                        .parse::<f64>()
                        .map_err(|_| format!("vertex coordinate `{w}` is not a number"))?;
                }
                corners.push(DVec3::from_array(xyz));
            }
            "loop" => {
                inside_loop = true;
                corners.clear();
            }
            "endloop" => {
                inside_loop = false;
                if corners.len() != 3 {
                    return Err(format!(
                        "facet {} has {} vertices (STL facets have 3)",
                        soup.len() + 1,
                        corners.len()
                    ));
                }
                if soup.len() == MAX_TRIANGLES {
                    return Err(format!("more than {MAX_TRIANGLES} triangles"));
                }
                soup.push([corners[0], corners[1], corners[2]]);
                line += 1;
            }
            _ => {}
        }
    }
    if inside_loop {
        return Err(format!("the file ends inside facet {}", line + 1));
    }
    Ok(soup)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn binary(triangles: &[[[f32; 3]; 3]]) -> Vec<u8> {
        let mut bytes = b"solid but binary".to_vec();
        bytes.resize(80, 0);
        bytes.extend((triangles.len() as u32).to_le_bytes());
        for t in triangles {
            bytes.extend([0_u8; 12]);
            for v in t {
                for c in v {
                    bytes.extend(c.to_le_bytes());
                }
            }
            bytes.extend([0_u8; 2]);
        }
        bytes
    }

    const TETRAHEDRON: [[[f32; 3]; 3]; 4] = [
        [[0.0, 0.0, 0.0], [0.0, 1.0, 0.0], [1.0, 0.0, 0.0]],
        [[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 0.0, 1.0]],
        [[0.0, 0.0, 0.0], [0.0, 0.0, 1.0], [0.0, 1.0, 0.0]],
        [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]],
    ];

    #[test]
    fn binary_and_ascii_give_the_same_mesh() {
        let from_binary = parse_stl(&binary(&TETRAHEDRON)).unwrap();
        let mut text = String::from("solid tet\n");
        for t in TETRAHEDRON {
            text.push_str("facet normal 0 0 0\n outer loop\n");
            for v in t {
                text.push_str(&format!("  vertex {} {} {}\n", v[0], v[1], v[2]));
            }
            text.push_str(" endloop\nendfacet\n");
        }
        text.push_str("endsolid tet\n");
        let from_ascii = parse_stl(text.as_bytes()).unwrap();
        assert_eq!(from_binary.vertices().len(), 4);
        assert_eq!(from_binary.triangles().len(), 4);
        assert_eq!(from_binary.vertices(), from_ascii.vertices());
        assert_eq!(from_binary.triangles(), from_ascii.triangles());
        assert!(from_binary.is_closed());
    }

    #[test]
    fn malformed_files_are_errors() {
        let mut truncated = binary(&TETRAHEDRON);
        truncated.pop();
        assert!(parse_stl(&truncated).is_err());
        assert!(parse_stl(b"solid x\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nendloop\nendfacet\n").is_err());
        assert!(parse_stl(b"solid x\nouter loop\nvertex 0 0 nan_x\n").is_err());
        assert!(parse_stl(b"solid empty\nendsolid empty\n").is_err());
        assert!(
            parse_stl(&binary(&[[
                [0.0, 0.0, f32::NAN],
                [1.0, 0.0, 0.0],
                [0.0, 1.0, 0.0]
            ]]))
            .is_err()
        );
        assert!(parse_stl(b"\x00\x01 not an stl").is_err());
    }
}
