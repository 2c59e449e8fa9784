//! Plain threads with a known stack, for work that must not run on a thread of rayon's
//! pool: a pool thread that waits (krilla waiting for its deferred chunks yields to the
//! pool, a `join` steals) runs whatever job is pending on its own stack, so that work of
//! unbounded count (a batch's variants) nested there overflows the stack. A plain thread
//! waits by blocking: what it runs is bounded by what it was given.
//!
//! Nothing here may be called from a pool thread and wait for a plain thread whose work
//! needs the pool (the pool could be all waiting): [`beside`] runs both parts on the
//! calling thread then.

use std::sync::atomic::{AtomicUsize, Ordering};
use std::sync::mpsc;

/// The stack of each plain thread, bytes: the main thread's (every run of `tmm` on one
/// scene does its whole work within it). Address space only until touched.
pub const STACK: usize = 8 << 20;

/// A plain thread of [`STACK`] in `scope`, running `f`; `None` when the system refuses one.
fn spawn<'s, 'e, T: Send + 's>(
    scope: &'s std::thread::Scope<'s, 'e>,
    f: impl FnOnce() -> T + Send + 's,
) -> Option<std::thread::ScopedJoinHandle<'s, T>> {
    std::thread::Builder::new()
        .stack_size(STACK)
        .spawn_scoped(scope, f)
        .ok()
}

/// The result of a plain thread; its panic goes on on the caller's.
fn joined<T>(handle: std::thread::ScopedJoinHandle<'_, T>) -> T {
    handle
        .join()
        .unwrap_or_else(|panic| std::panic::resume_unwind(panic))
}

/// `a` and `b` side by side: `a` on a plain thread, `b` on the calling thread. On a thread
/// of rayon's pool, or when no thread can be had, `b` then `a` on the calling thread.
pub fn beside<A: Send, B>(a: impl FnOnce() -> A + Send, b: impl FnOnce() -> B) -> (A, B) {
    if rayon::current_thread_index().is_some() {
        let b = b();
        return (a(), b);
    }
    // `a` is kept for the calling thread when no thread takes it.
    let a = std::sync::Mutex::new(Some(a));
    let take = || a.lock().ok().and_then(|mut a| a.take());
    std::thread::scope(|scope| {
        let handle = spawn(scope, || take().map(|a| a()));
        let b = b();
        let a = match handle.and_then(joined) {
            Some(a) => a,
            None => match take() {
                Some(a) => a(),
                // The thread took `a` and gave nothing back: it cannot, but the poisoned
                // lock is the one way there.
                None => std::panic::resume_unwind(Box::new("a thread lost its work")),
            },
        };
        (a, b)
    })
}

/// `f` of every item of `items` on `workers` plain threads (at least one) taking the next
/// item as each finishes — at most `workers` items in hand at once — and `done` on the
/// calling thread with each item's index and result as it comes. When no thread can be
/// had, the calling thread does the items itself.
pub fn each<T: Sync, R: Send>(
    items: &[T],
    workers: usize,
    f: impl Fn(&T) -> R + Sync,
    mut done: impl FnMut(usize, R),
) {
    let next = AtomicUsize::new(0);
    let work = |send: &mut dyn FnMut(usize, R)| loop {
        let k = next.fetch_add(1, Ordering::Relaxed);
        let Some(item) = items.get(k) else { break };
        send(k, f(item));
    };
    std::thread::scope(|scope| {
        let (tx, rx) = mpsc::channel::<(usize, R)>();
        let handles: Vec<_> = (0..workers.max(1))
            .filter_map(|_| {
                let tx = tx.clone();
                let work = &work;
                spawn(scope, move || work(&mut |k, r| drop(tx.send((k, r)))))
            })
            .collect();
        drop(tx);
        if handles.is_empty() {
            work(&mut done);
            return;
        }
        for (k, r) in rx {
            done(k, r);
        }
        for h in handles {
            joined(h);
        }
    });
}

#[cfg(test)]
mod tests {
    use super::*;
    use rayon::prelude::*;

    #[test]
    fn each_gives_every_result_once_with_its_index() {
        let items: Vec<u64> = (0..500).collect();
        let mut got = vec![None; items.len()];
        each(&items, 3, |x| x * x, |k, r| got[k] = Some(r));
        assert!(got
            .iter()
            .enumerate()
            .all(|(k, r)| *r == Some((k * k) as u64)));
        let mut none = 0;
        each(&[] as &[u8], 4, |_| (), |_, _| none += 1);
        assert_eq!(none, 0);
    }

    #[test]
    fn each_runs_off_the_pool_and_never_nests_an_item_in_another() {
        // Each item waits on the pool (a parallel sum): on a pool thread a waiting item could
        // take up the next item on its stack; on plain threads none is ever inside another.
        let depth = AtomicUsize::new(0);
        let deepest = AtomicUsize::new(0);
        let items: Vec<u64> = (0..2000).collect();
        let mut sum = 0;
        each(
            &items,
            2,
            |&x| {
                assert!(rayon::current_thread_index().is_none());
                let d = depth.fetch_add(1, Ordering::SeqCst) + 1;
                deepest.fetch_max(d, Ordering::SeqCst);
                let s: u64 = (0..64u64).into_par_iter().map(|y| y + x).sum();
                depth.fetch_sub(1, Ordering::SeqCst);
                s
            },
            |_, s| sum += s,
        );
        assert_eq!(sum, (0..2000u64).map(|x| 64 * x + 2016).sum::<u64>());
        assert!(deepest.load(Ordering::SeqCst) <= 2);
    }

    #[test]
    fn beside_gives_both_results_on_and_off_the_pool() {
        let (a, b) = beside(rayon::current_thread_index, || 2);
        assert_eq!((a, b), (None, 2));
        let (a, b) = rayon::scope(|_| beside(|| 1, || 2));
        assert_eq!((a, b), (1, 2));
    }
}
