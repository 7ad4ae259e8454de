//! `tw_part`: a STEP part read into memory with its adjacency graph.

use crate::error::{construct, count, free, guard, null, study_failure, tw_status, Failure};
use std::ffi::{c_char, CStr};

/// A part read from STEP (opaque). Immutable; safe to share between threads.
pub struct tw_part {
    /// The part, what the reader reported and its graph.
    pub(crate) loaded: thinwall_study::LoadedPart,
}

/// The part at `part`; NULL is an error naming the argument.
pub(crate) unsafe fn part_ref<'a>(part: *const tw_part) -> Result<&'a tw_part, Failure> {
    if part.is_null() {
        return Err(null("part"));
    }
    Ok(&*part)
}

// A part is shared between a host's threads: it must stay Send and Sync.
const _: fn() = || {
    fn shared<T: Send + Sync>() {}
    shared::<tw_part>();
};

impl tw_part {
    /// Run `work` on a study of the part made for this call (no worker
    /// threads unless `parallel`). A study kept with the part would share
    /// its analysis between calls, but its locks are futexes that
    /// valgrind's helgrind cannot follow between a host's threads (the
    /// threads test reports them as races), so each call has its own.
    pub(crate) fn with_study<R>(
        &self,
        parallel: bool,
        work: impl for<'s> FnOnce(&thinwall_study::Study<'s>) -> R,
    ) -> R {
        work(&thinwall_study::Study::new(&self.loaded).with_parallelism(parallel))
    }
}

/// A part from a read (a panic in it named with the file), with its
/// adjacency graph.
fn finish(
    read: Result<thinwall_study::LoadedPart, thinwall_study::StudyError>,
) -> Result<tw_part, Failure> {
    Ok(tw_part {
        loaded: read.map_err(study_failure)?,
    })
}

/// Read the STEP file at `path` (UTF-8). On success `*out` owns a part to
/// free with `tw_part_free`; on failure `*out` is NULL.
#[no_mangle]
pub unsafe extern "C" fn tw_part_load_file(
    path: *const c_char,
    out: *mut *mut tw_part,
) -> tw_status {
    construct("tw_part_load_file", out, || {
        if path.is_null() {
            return Err(null("path"));
        }
        let p = CStr::from_ptr(path).to_str().map_err(|_| {
            (
                tw_status::TW_ERR_INVALID_ARGUMENT,
                "path is not UTF-8".to_string(),
            )
        })?;
        finish(thinwall_study::LoadedPart::read_file(p))
    })
}

/// Read STEP text from `len` bytes at `data`. On success `*out` owns a part
/// to free with `tw_part_free`; on failure `*out` is NULL.
#[no_mangle]
pub unsafe extern "C" fn tw_part_load_memory(
    data: *const u8,
    len: usize,
    out: *mut *mut tw_part,
) -> tw_status {
    construct("tw_part_load_memory", out, || {
        if data.is_null() {
            return Err(null("data"));
        }
        let bytes = std::slice::from_raw_parts(data, len);
        finish(thinwall_study::LoadedPart::read_bytes(bytes, "<memory>"))
    })
}

/// Number of faces of the part's solid bodies (0 for NULL).
#[no_mangle]
pub unsafe extern "C" fn tw_part_face_count(part: *const tw_part) -> usize {
    count(part, |p| p.loaded.part.faces.len())
}

/// The ordinal of face (`body`, `step_id`) — as every result names a face —
/// in the order OpenCascade numbers the faces of the shape it reads from
/// the same file (`TopExp::MapShapes(shape, TopAbs_FACE, map)`, from 0:
/// `map.FindKey(*ordinal + 1)`; FreeCAD's `Shape.Faces[*ordinal]`).
/// `TW_ERR_OUT_OF_RANGE` when the part has no such face.
#[no_mangle]
pub unsafe extern "C" fn tw_part_face_occ_index(
    part: *const tw_part,
    body: u32,
    step_id: u64,
    ordinal: *mut u32,
) -> tw_status {
    guard("tw_part_face_occ_index", || {
        let p = &part_ref(part)?.loaded.part;
        if ordinal.is_null() {
            return Err(null("ordinal"));
        }
        let found = p
            .faces
            .iter()
            .position(|f| f.body.0 == body && f.step_id == step_id)
            .and_then(|i| p.occ_ordinals.get(i));
        match found {
            Some(&o) => {
                *ordinal = o;
                Ok(())
            }
            None => Err((
                tw_status::TW_ERR_OUT_OF_RANGE,
                format!("no face #{step_id} in body {body}"),
            )),
        }
    })
}

/// Free a part. NULL is allowed.
#[no_mangle]
pub unsafe extern "C" fn tw_part_free(part: *mut tw_part) {
    free(part)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_face_of_each_placed_instance_has_its_own_opencascade_ordinal() {
        let path = concat!(
            env!("CARGO_MANIFEST_DIR"),
            "/../fixtures/bracket_assembly.step\0"
        );
        let mut part: *mut tw_part = std::ptr::null_mut();
        unsafe {
            assert_eq!(
                tw_part_load_file(path.as_ptr().cast(), &mut part),
                tw_status::TW_OK
            );
            let mut ordinal = u32::MAX;
            // Two instances of one 18-face bracket: the second's faces follow.
            assert_eq!(
                tw_part_face_occ_index(part, 0, 39, &mut ordinal),
                tw_status::TW_OK
            );
            assert_eq!(ordinal, 0);
            assert_eq!(
                tw_part_face_occ_index(part, 1, 39, &mut ordinal),
                tw_status::TW_OK
            );
            assert_eq!(ordinal, 18);
            assert_eq!(
                tw_part_face_occ_index(part, 2, 39, &mut ordinal),
                tw_status::TW_ERR_OUT_OF_RANGE
            );
            assert_eq!(
                tw_part_face_occ_index(part, 0, 39, std::ptr::null_mut()),
                tw_status::TW_ERR_NULL_ARGUMENT
            );
            assert_eq!(
                tw_part_face_occ_index(std::ptr::null(), 0, 39, &mut ordinal),
                tw_status::TW_ERR_NULL_ARGUMENT
            );
            tw_part_free(part);
        }
    }
}
