//! `tw_result`: the recognition of a part, with typed accessors and the
//! same JSON as `thinwall recognize --format json`.

use crate::error::{
    construct, count, cstring, free, guard, json_into, null, string_at, study_failure, tw_status,
};
use crate::options::{options_or_default, tw_options};
use crate::part::{part_ref, tw_part};
use std::ffi::{c_char, CString};
use thinwall_connect::Connection;
use thinwall_report::RecognitionReport;

/// A recognition result (opaque). Immutable; safe to share between threads.
/// Strings it returns live as long as it does.
pub struct tw_result {
    report: RecognitionReport,
    ids: Vec<CString>,
    kinds: Vec<CString>,
    /// Per connection: kind and its two feature ids.
    links: Vec<(tw_connection_kind, CString, CString)>,
    /// Per machining feature: its id and kind.
    machining_ids: Vec<CString>,
    machining_kinds: Vec<CString>,
}

impl tw_result {
    pub(crate) fn report(&self) -> &RecognitionReport {
        &self.report
    }

    pub(crate) fn machining_ids(&self) -> &[CString] {
        &self.machining_ids
    }

    pub(crate) fn machining_kinds(&self) -> &[CString] {
        &self.machining_kinds
    }
}

/// The kind of a connection.
#[repr(C)]
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum tw_connection_kind {
    /// `first` is the base, `second` the leaf on or in it.
    TW_CONNECTION_BASE_LEAF = 0,
    /// `first` and `second` cross (meet and share a base).
    TW_CONNECTION_CROSSING = 1,
}

/// Recognize stiffness features and their connections. `opt` may be NULL
/// for the defaults. On success `*out` owns a result to free with
/// `tw_result_free`; on failure `*out` is NULL.
#[no_mangle]
pub unsafe extern "C" fn tw_recognize(
    part: *const tw_part,
    opt: *const tw_options,
    out: *mut *mut tw_result,
) -> tw_status {
    construct("tw_recognize", out, || {
        let p = part_ref(part)?;
        let o = options_or_default(opt);
        let report = p
            .with_study(o.request.parallel, |study| {
                thinwall_study::recognize(study, &o.request).map(|r| r.report)
            })
            .map_err(study_failure)?;
        let feats = &report.stiffness_features;
        let ids = feats
            .iter()
            .map(|e| cstring(&e.feature.id.to_string()))
            .collect();
        let kinds = feats
            .iter()
            .map(|e| cstring(e.feature.kind.name()))
            .collect();
        let links = report
            .connections
            .iter()
            .map(|c| match c {
                Connection::BaseLeaf { base, leaf } => (
                    tw_connection_kind::TW_CONNECTION_BASE_LEAF,
                    cstring(&base.to_string()),
                    cstring(&leaf.to_string()),
                ),
                Connection::Crossing { features } => (
                    tw_connection_kind::TW_CONNECTION_CROSSING,
                    cstring(&features[0].to_string()),
                    cstring(&features[1].to_string()),
                ),
            })
            .collect();
        let machining = &report.machining_features;
        let machining_ids = machining
            .iter()
            .map(|m| cstring(&m.id.to_string()))
            .collect();
        let machining_kinds = machining.iter().map(|m| cstring(m.kind.name())).collect();
        Ok(tw_result {
            report,
            ids,
            kinds,
            links,
            machining_ids,
            machining_kinds,
        })
    })
}

/// Free a result. NULL is allowed.
#[no_mangle]
pub unsafe extern "C" fn tw_result_free(res: *mut tw_result) {
    free(res)
}

/// The result as JSON (`thinwall/recognition/1`, as the CLI prints it).
/// `*out_json` is a new string to free with `tw_string_free`.
#[no_mangle]
pub unsafe extern "C" fn tw_result_to_json(
    res: *const tw_result,
    out_json: *mut *mut c_char,
) -> tw_status {
    json_into("tw_result_to_json", res, out_json, |r| r.report.to_json())
}

/// Number of stiffness features (0 for NULL).
#[no_mangle]
pub unsafe extern "C" fn tw_result_feature_count(res: *const tw_result) -> usize {
    count(res, |r| r.ids.len())
}

/// Kind of feature `i` ("web", "rib", "flange", "wall", "hole", "cutout",
/// "notch", "chamfer", "fillet"); NULL when `res` is NULL or `i` is out of
/// range. Valid while `res` lives.
#[no_mangle]
pub unsafe extern "C" fn tw_result_feature_kind(res: *const tw_result, i: usize) -> *const c_char {
    string_at(res, |r| r.kinds.get(i))
}

/// Id of feature `i` ("R2", "H1", …; stable within the result); NULL when
/// out of range. Valid while `res` lives.
#[no_mangle]
pub unsafe extern "C" fn tw_result_feature_id(res: *const tw_result, i: usize) -> *const c_char {
    string_at(res, |r| r.ids.get(i))
}

/// Wall sizes of feature `i`, mm: thickness, height (foot to free edge, or
/// for a web the largest distance to a supporting wall), length; `*thin` is
/// whether it needs stiffness support. Any out-pointer may be NULL.
/// `TW_ERR_NOT_APPLICABLE` for a feature that is not a wall.
#[no_mangle]
pub unsafe extern "C" fn tw_result_feature_wall(
    res: *const tw_result,
    i: usize,
    thickness: *mut f64,
    height: *mut f64,
    length: *mut f64,
    thin: *mut bool,
) -> tw_status {
    guard("tw_result_feature_wall", || {
        let f = &stiffness_feature(res, i)?.feature;
        if !f.kind.is_wall() {
            return Err((
                tw_status::TW_ERR_NOT_APPLICABLE,
                format!("{} is a {}, not a wall", f.id, f.kind.name()),
            ));
        }
        for (ptr, v) in [
            (thickness, f.thickness),
            (height, f.height),
            (length, f.length),
        ] {
            if !ptr.is_null() {
                *ptr = v.unwrap_or(f64::NAN);
            }
        }
        if !thin.is_null() {
            *thin = f.thin == Some(true);
        }
        Ok(())
    })
}

/// A wall running through its base to both of its sides (a frame's outer
/// wall, a rib through a double-sided web): its height on the base's other
/// side, mm, and whether that part needs stiffness support
/// (`tw_result_feature_wall`'s height is on the side this set-up
/// machines). Any out-pointer may be NULL. `TW_ERR_NOT_APPLICABLE` for a
/// feature that is not a wall or stands on one side of its base only.
#[no_mangle]
pub unsafe extern "C" fn tw_result_feature_other_side(
    res: *const tw_result,
    i: usize,
    height: *mut f64,
    thin: *mut bool,
) -> tw_status {
    guard("tw_result_feature_other_side", || {
        let f = &stiffness_feature(res, i)?.feature;
        let o = f.other_side.as_ref().ok_or_else(|| {
            (
                tw_status::TW_ERR_NOT_APPLICABLE,
                format!("{} does not run through its base", f.id),
            )
        })?;
        if !height.is_null() {
            *height = o.height;
        }
        if !thin.is_null() {
            *thin = o.thin;
        }
        Ok(())
    })
}

/// The STEP entity ids of feature `i`'s faces. With `buf` NULL, only
/// `*len` is written (a length query). Otherwise, when `cap` is too small,
/// `*len` gets the needed length and `TW_ERR_BUFFER_TOO_SMALL` is returned;
/// else the ids are copied and `*len` is their count.
#[no_mangle]
pub unsafe extern "C" fn tw_result_feature_faces(
    res: *const tw_result,
    i: usize,
    buf: *mut u64,
    cap: usize,
    len: *mut usize,
) -> tw_status {
    guard("tw_result_feature_faces", || {
        if res.is_null() {
            return Err(null("res"));
        }
        if len.is_null() {
            return Err(null("len"));
        }
        let f = &(&*res)
            .report
            .stiffness_features
            .get(i)
            .ok_or((
                tw_status::TW_ERR_OUT_OF_RANGE,
                format!("feature {i} out of range"),
            ))?
            .feature;
        *len = f.faces.len();
        if buf.is_null() {
            return Ok(());
        }
        if cap < f.faces.len() {
            return Err((
                tw_status::TW_ERR_BUFFER_TOO_SMALL,
                format!("{} ids need a buffer of {}", f.faces.len(), f.faces.len()),
            ));
        }
        std::ptr::copy_nonoverlapping(f.faces.as_ptr(), buf, f.faces.len());
        Ok(())
    })
}

/// Number of connections (0 for NULL).
#[no_mangle]
pub unsafe extern "C" fn tw_result_connection_count(res: *const tw_result) -> usize {
    count(res, |r| r.links.len())
}

/// Connection `i`: its kind and the ids of its two features (for base-leaf:
/// base first). The strings live as long as `res`. Any out-pointer may be NULL.
#[no_mangle]
pub unsafe extern "C" fn tw_result_connection(
    res: *const tw_result,
    i: usize,
    kind: *mut tw_connection_kind,
    first: *mut *const c_char,
    second: *mut *const c_char,
) -> tw_status {
    guard("tw_result_connection", || {
        if res.is_null() {
            return Err(null("res"));
        }
        let (k, a, b) = (&*res).links.get(i).ok_or((
            tw_status::TW_ERR_OUT_OF_RANGE,
            format!("connection {i} out of range"),
        ))?;
        if !kind.is_null() {
            *kind = *k;
        }
        if !first.is_null() {
            *first = a.as_ptr();
        }
        if !second.is_null() {
            *second = b.as_ptr();
        }
        Ok(())
    })
}

/// Stiffness feature `i` of `res`: a NULL result or an index out of range
/// is the error to return.
unsafe fn stiffness_feature<'a>(
    res: *const tw_result,
    i: usize,
) -> Result<&'a thinwall_report::recognize::FeatureEntry, crate::error::Failure> {
    if res.is_null() {
        return Err(null("res"));
    }
    (&*res).report.stiffness_features.get(i).ok_or((
        tw_status::TW_ERR_OUT_OF_RANGE,
        format!("feature {i} out of range"),
    ))
}
