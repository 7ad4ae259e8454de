//! Results computed at most once per key: a small list guarded by a lock
//! (a study holds a handful of set-ups and requests, never thousands).

use std::sync::{Arc, Mutex};

/// Values by key; a value is computed once and shared.
pub(crate) struct Memo<K, V> {
    entries: Mutex<Vec<(K, Arc<V>)>>,
}

impl<K, V> Default for Memo<K, V> {
    fn default() -> Self {
        Self {
            entries: Mutex::new(Vec::new()),
        }
    }
}

impl<K: PartialEq + Clone, V> Memo<K, V> {
    /// The value for `key`, computed by `make` the first time. A failure
    /// is returned and not kept (the next call tries again). The lock is
    /// held while `make` runs, so two threads never compute one value.
    pub(crate) fn get_or_try<E>(
        &self,
        key: &K,
        make: impl FnOnce() -> Result<V, E>,
    ) -> Result<Arc<V>, E> {
        let mut entries = self.entries.lock().unwrap_or_else(|p| p.into_inner());
        if let Some((_, v)) = entries.iter().find(|(k, _)| k == key) {
            return Ok(v.clone());
        }
        let v = Arc::new(make()?);
        entries.push((key.clone(), v.clone()));
        Ok(v)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn computes_once_per_key_and_keeps_no_failure() {
        let m: Memo<u32, String> = Memo::default();
        let calls = std::cell::Cell::new(0);
        let make = |v: &str| {
            calls.set(calls.get() + 1);
            Ok::<_, ()>(v.to_string())
        };
        assert_eq!(*m.get_or_try(&1, || make("a")).unwrap(), "a");
        assert_eq!(*m.get_or_try(&1, || make("b")).unwrap(), "a");
        assert_eq!(*m.get_or_try(&2, || make("c")).unwrap(), "c");
        assert_eq!(calls.get(), 2);
        assert!(m.get_or_try(&3, || Err::<String, _>(())).is_err());
        assert_eq!(*m.get_or_try(&3, || make("d")).unwrap(), "d");
    }
}
