//! Waiting on two things at once: [`race`] of two futures, and [`stopped`],
//! the end of the server's stop signal. Below the connections, the answers
//! and the child runs, which all wait on a run or a read and the stop.

use std::future::{poll_fn, Future};
use std::pin::pin;
use std::task::Poll;

use tokio::sync::watch;

/// One of two.
#[derive(Debug)]
pub enum Either<A, B> {
    /// The first.
    Left(A),
    /// The second.
    Right(B),
}

/// Whichever of `a` and `b` ends first (`a` when both are ready); the other
/// is dropped.
pub async fn race<A: Future, B: Future>(a: A, b: B) -> Either<A::Output, B::Output> {
    let (mut a, mut b) = (pin!(a), pin!(b));
    poll_fn(|cx| {
        if let Poll::Ready(x) = a.as_mut().poll(cx) {
            return Poll::Ready(Either::Left(x));
        }
        if let Poll::Ready(y) = b.as_mut().poll(cx) {
            return Poll::Ready(Either::Right(y));
        }
        Poll::Pending
    })
    .await
}

/// Ends when `stop` turns true (at once if it is).
pub async fn stopped(mut stop: watch::Receiver<bool>) {
    // An error: the sender is gone, which only a stopping server does.
    let _ = stop.wait_for(|s| *s).await;
}
