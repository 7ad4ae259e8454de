//! `libthinwall.so` and `libthinwall.a`: every `tw_*` entry point of
//! `thinwall-capi` (`plugin-api/src`), linked into the C library. A
//! `#[no_mangle] extern "C"` function of a crate linked in is exported by
//! the cdylib and the staticlib alike; the re-export links it.

pub use thinwall_capi::*;
