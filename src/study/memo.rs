//! Caches of results computed once per key, shared by reference: one [`Memo`] per study's
//! [`Cache`], kept by the session in its [`Caches`].

use std::any::{Any, TypeId};
use std::sync::{Arc, Mutex, OnceLock};

/// What one cache of a study holds: a marker type, declared in the study's own file, names
/// its key and its value. The session keeps one [`Memo`] per marker, so adding a study adds
/// no field to the session.
pub(crate) trait Cache: 'static {
    /// What a result is computed for (a position, a scale…).
    type Key: PartialEq + Send + 'static;
    /// The result, shared by every asker.
    type Value: Clone + Send + Sync + 'static;
}

/// The memos of every [`Cache`] asked for so far, each created on first use.
#[derive(Default)]
pub(crate) struct Caches {
    memos: Mutex<Vec<(TypeId, Arc<dyn Any + Send + Sync>)>>,
}

impl Caches {
    /// The value of cache `C` for `key`, computed by `f` the first time. The lock over the
    /// memos is released before `f` runs, so `f` may ask any cache.
    pub fn get<C: Cache>(&self, key: C::Key, f: impl FnOnce() -> C::Value) -> C::Value {
        self.memo::<C>().get(key, f)
    }

    fn memo<C: Cache>(&self) -> Arc<Memo<C::Key, C::Value>> {
        let id = TypeId::of::<C>();
        let mut memos = self.memos.lock().unwrap_or_else(|e| e.into_inner());
        let found = memos
            .iter()
            .find(|(t, _)| *t == id)
            .and_then(|(_, m)| Arc::clone(m).downcast().ok());
        found.unwrap_or_else(|| {
            let m = Arc::new(Memo::default());
            memos.push((id, Arc::clone(&m) as Arc<dyn Any + Send + Sync>));
            m
        })
    }
}

/// Values computed on demand, once per key; later requests get the same `Arc`. A slot is
/// created under the lock and filled outside it, so a computation may ask for other keys
/// (an acceleration plan asks for its velocity plan) and two threads asking for the same key
/// compute it once.
pub(crate) struct Memo<K, V> {
    slots: Mutex<Vec<(K, Arc<OnceLock<V>>)>>,
}

impl<K, V> Default for Memo<K, V> {
    fn default() -> Self {
        Self {
            slots: Mutex::new(Vec::new()),
        }
    }
}

impl<K: PartialEq, V: Clone> Memo<K, V> {
    /// The value for `key`, computed by `f` the first time.
    pub fn get(&self, key: K, f: impl FnOnce() -> V) -> V {
        let slot = {
            // A poisoned lock means a computation panicked; the slots themselves are intact.
            let mut slots = self.slots.lock().unwrap_or_else(|e| e.into_inner());
            match slots.iter().find(|(k, _)| *k == key) {
                Some((_, s)) => Arc::clone(s),
                None => {
                    let s = Arc::new(OnceLock::new());
                    slots.push((key, Arc::clone(&s)));
                    s
                }
            }
        };
        slot.get_or_init(f).clone()
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::cell::Cell;

    #[test]
    fn computes_once_per_key() {
        let memo: Memo<u32, Arc<String>> = Memo::default();
        let calls = Cell::new(0);
        let make = |s: &str| {
            calls.set(calls.get() + 1);
            Arc::new(s.to_string())
        };
        let a = memo.get(1, || make("one"));
        let b = memo.get(1, || make("again"));
        let c = memo.get(2, || make("two"));
        assert!(Arc::ptr_eq(&a, &b));
        assert_eq!((a.as_str(), c.as_str(), calls.get()), ("one", "two", 2));
    }

    struct Squares;
    impl Cache for Squares {
        type Key = u32;
        type Value = u64;
    }
    struct Names;
    impl Cache for Names {
        type Key = u32;
        type Value = u64;
    }

    #[test]
    fn each_cache_type_has_its_own_memo() {
        // Same key and value types, two markers: two caches, and one may ask the other.
        let caches = Caches::default();
        let a = caches.get::<Squares>(3, || caches.get::<Names>(3, || 30) + 9);
        assert_eq!(a, 39);
        assert_eq!(caches.get::<Squares>(3, || 0), 39);
        assert_eq!(caches.get::<Names>(3, || 0), 30);
    }

    #[test]
    fn a_computation_may_ask_for_another_key() {
        let memo: Memo<u32, u64> = Memo::default();
        let v = memo.get(2, || memo.get(1, || 20) + 1);
        assert_eq!((v, memo.get(1, || 0)), (21, 20));
    }
}
