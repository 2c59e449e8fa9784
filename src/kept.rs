//! The last few results of a pure function, kept for the next caller asking the same: a
//! class's variants share what the grid does not change (the gear pair's blocking contour,
//! the sheets drawn from it), and each is made about once per run.
//!
//! Nothing waits for a result being made: a second caller asking meanwhile makes it too. A
//! wait could be a deadlock — the making thread, inside a parallel loop of its own, may take
//! up another task that asks for the same result.

use std::sync::{Mutex, PoisonError};

/// At most `most` results, the newest last; keys compared with `==`.
pub struct Recent<K, V> {
    items: Mutex<Vec<(K, V)>>,
    most: usize,
}

impl<K: PartialEq, V: Clone> Recent<K, V> {
    /// An empty store of at most `most` results.
    pub const fn new(most: usize) -> Self {
        Self {
            items: Mutex::new(Vec::new()),
            most,
        }
    }

    fn items(&self) -> std::sync::MutexGuard<'_, Vec<(K, V)>> {
        self.items.lock().unwrap_or_else(PoisonError::into_inner)
    }

    /// The kept result whose key `same` picks.
    pub fn find(&self, same: impl Fn(&K) -> bool) -> Option<V> {
        self.items()
            .iter()
            .find(|(k, _)| same(k))
            .map(|(_, v)| v.clone())
    }

    /// Keep `value` for `key` (unless a result for it is kept already), the oldest dropped
    /// beyond `most`.
    pub fn keep(&self, key: K, value: V) {
        let mut items = self.items();
        if items.iter().any(|(k, _)| *k == key) {
            return;
        }
        if items.len() >= self.most {
            drop(items.remove(0));
        }
        items.push((key, value));
    }

    /// Forget every result (the bench times each run as a fresh process).
    pub fn clear(&self) {
        self.items().clear();
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn keeps_the_newest_once_each() {
        let r: Recent<u32, &str> = Recent::new(2);
        r.keep(1, "a");
        r.keep(1, "again");
        r.keep(2, "b");
        assert_eq!(r.find(|k| *k == 1), Some("a"));
        r.keep(3, "c");
        assert_eq!(r.find(|k| *k == 1), None, "the oldest dropped");
        assert_eq!(r.find(|k| *k == 3), Some("c"));
        r.clear();
        assert_eq!(r.find(|k| *k == 2), None);
    }
}
