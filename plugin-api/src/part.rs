//! `tw_part`: a STEP part read into memory with its adjacency graph.

use crate::error::{guard, null, tw_status};
use std::ffi::{c_char, CStr};
use thinwall_brep::Part;
use thinwall_graph::AdjacencyGraph;

/// A part read from STEP (opaque). Immutable; safe to share between threads.
pub struct tw_part {
    pub(crate) name: String,
    pub(crate) part: Part,
    pub(crate) graph: AdjacencyGraph,
}

fn status_of(e: &thinwall_step::StepError) -> tw_status {
    match e.code() {
        "io" => tw_status::TW_ERR_IO,
        "syntax" => tw_status::TW_ERR_PARSE,
        "no_brep" => tw_status::TW_ERR_NO_BREP,
        "open_shell" | "id_mismatch" => tw_status::TW_ERR_INVALID_PART,
        _ => tw_status::TW_ERR_INTERNAL,
    }
}

fn finish(
    read: Result<(Part, thinwall_step::ReadReport), thinwall_step::StepError>,
    name: String,
    out: *mut *mut tw_part,
) -> Result<(), (tw_status, String)> {
    let (part, _) = read.map_err(|e| (status_of(&e), e.to_string()))?;
    let graph = AdjacencyGraph::build(&part, &part.tolerances());
    let boxed = Box::new(tw_part { name, part, graph });
    unsafe { *out = Box::into_raw(boxed) };
    Ok(())
}

/// Read the STEP file at `path` (UTF-8). On success `*out` owns a part to
/// free with `tw_part_free`; on failure `*out` is NULL.
#[no_mangle]
pub unsafe extern "C" fn tw_part_load_file(
    path: *const c_char,
    out: *mut *mut tw_part,
) -> tw_status {
    if !out.is_null() {
        *out = std::ptr::null_mut();
    }
    guard(|| {
        if out.is_null() {
            return Err(null("out"));
        }
        if path.is_null() {
            return Err(null("path"));
        }
        let p = CStr::from_ptr(path).to_str().map_err(|_| {
            (
                tw_status::TW_ERR_INVALID_ARGUMENT,
                "path is not UTF-8".to_string(),
            )
        })?;
        finish(thinwall_step::read_file(p), p.to_string(), out)
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
    if !out.is_null() {
        *out = std::ptr::null_mut();
    }
    guard(|| {
        if out.is_null() {
            return Err(null("out"));
        }
        if data.is_null() {
            return Err(null("data"));
        }
        let bytes = std::slice::from_raw_parts(data, len);
        finish(
            thinwall_step::read_bytes(bytes, "<memory>"),
            "<memory>".to_string(),
            out,
        )
    })
}

/// Number of faces of the part's solid bodies (0 for NULL).
#[no_mangle]
pub unsafe extern "C" fn tw_part_face_count(part: *const tw_part) -> usize {
    if part.is_null() {
        return 0;
    }
    std::panic::catch_unwind(|| (&*part).part.faces.len()).unwrap_or(0)
}

/// Free a part. NULL is allowed.
#[no_mangle]
pub unsafe extern "C" fn tw_part_free(part: *mut tw_part) {
    if !part.is_null() {
        let _ = std::panic::catch_unwind(|| drop(Box::from_raw(part)));
    }
}
