//! The fuzz check of the Wavefront OBJ reader and the mesh validation behind it.

use crate::mesh::{catmull_clark, read_obj, write_obj, PolygonMesh};
use num_rational::BigRational;

/// Runs [`read_obj`] on `data` in `f64` and in exact rationals. Neither may panic; a mesh
/// either accepts must pass [`MeshTopology::check`](crate::mesh::MeshTopology::check), read
/// back from [`write_obj`] with the same positions and faces, and keep its Euler
/// characteristic and invariants through a round of Catmull–Clark (below 4096 corners); when
/// both accept, the faces are the same.
pub fn obj(data: &[u8]) {
    let rounded = read_obj::<f64>(data);
    let exact = read_obj::<BigRational>(data);
    if let Ok(mesh) = &rounded {
        check_mesh(mesh);
    }
    if let Ok(mesh) = &exact {
        mesh.topology()
            .check()
            .expect("a mesh read exactly is valid");
    }
    if let (Ok(a), Ok(b)) = (&rounded, &exact) {
        assert_eq!(
            a.topology(),
            b.topology(),
            "the same faces in f64 and exactly"
        );
    }
}

fn check_mesh(mesh: &PolygonMesh<f64, 3>) {
    let t = mesh.topology();
    t.check().expect("an accepted mesh keeps its invariants");
    let mut text = Vec::new();
    write_obj(mesh, &mut text).expect("writing to a vector");
    let back = read_obj::<f64>(&text[..]).expect("a written mesh reads back");
    assert_eq!(back.positions(), mesh.positions(), "positions round-trip");
    assert_eq!(back.topology().corners(), t.corners(), "faces round-trip");
    assert_eq!(back.topology().face_offsets(), t.face_offsets());
    if t.halfedge_count() <= 4096 {
        let fine = catmull_clark(mesh, 1).expect("one round fits");
        fine.topology()
            .check()
            .expect("a refined mesh keeps its invariants");
        assert_eq!(fine.euler_characteristic(), mesh.euler_characteristic());
        assert_eq!(fine.face_count(), t.halfedge_count());
    }
}
