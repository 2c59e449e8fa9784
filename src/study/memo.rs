//! A cache of results computed once per key, shared by reference.

use std::sync::{Arc, Mutex, OnceLock};

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

    #[test]
    fn a_computation_may_ask_for_another_key() {
        let memo: Memo<u32, u64> = Memo::default();
        let v = memo.get(2, || memo.get(1, || 20) + 1);
        assert_eq!((v, memo.get(1, || 0)), (21, 20));
    }
}
