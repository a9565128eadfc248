//! Data ports: `OutPort<T>` writes to every connected `InPort<T>` (spec §1 "Ports").
//!
//! **Decision**: an InPort holds the newest value only (OpenRTM's buffer of length one with
//! overwrite), which is what the seeds' `isNew()` / `read()` pattern needs. Ports are
//! single-threaded (`Rc<RefCell<…>>`): the whole system runs in one execution context.

use std::cell::RefCell;
use std::fmt;
use std::rc::Rc;

#[derive(Debug)]
struct Slot<T> {
    value: Option<T>,
    new: bool,
}

/// An input data port.
pub struct InPort<T> {
    name: &'static str,
    slot: Rc<RefCell<Slot<T>>>,
}

impl<T> InPort<T> {
    /// A port with the seed's name (e.g. `InCurrentPosition`).
    pub fn new(name: &'static str) -> Self {
        Self {
            name,
            slot: Rc::new(RefCell::new(Slot {
                value: None,
                new: false,
            })),
        }
    }

    /// The port's name.
    pub fn name(&self) -> &'static str {
        self.name
    }

    /// Whether data arrived that has not been read (`isNew()`).
    pub fn is_new(&self) -> bool {
        self.slot.borrow().new
    }

    /// Drops any unread data (OpenRTM's buffer update in `on_activated`, 002 §5.2.3 (3)).
    pub fn clear(&self) {
        let mut s = self.slot.borrow_mut();
        s.value = None;
        s.new = false;
    }

    /// Writes directly into this port, as a connected `OutPort` would (for tests and hosts).
    pub fn put(&self, value: T) {
        let mut s = self.slot.borrow_mut();
        s.value = Some(value);
        s.new = true;
    }
}

impl<T: Clone> InPort<T> {
    /// Takes the newest value (`read()`): afterwards `is_new()` is false until the next write.
    /// Returns `None` if nothing was ever written.
    pub fn read(&self) -> Option<T> {
        let mut s = self.slot.borrow_mut();
        s.new = false;
        s.value.clone()
    }

    /// The newest value without marking it read.
    pub fn peek(&self) -> Option<T> {
        self.slot.borrow().value.clone()
    }
}

impl<T: Clone> InPort<T> {
    /// The same port (not a copy): what an [`OutPort`] is connected to when a copied system
    /// is connected again ([`OutPort::connect`] takes it by reference).
    pub(crate) fn share(&self) -> Self {
        Self {
            name: self.name,
            slot: Rc::clone(&self.slot),
        }
    }
}

/// A copy is a port of its own holding the same value and `isNew()` flag; it is connected
/// to nothing until its owner connects it (a copied system connects its ports as the
/// original was connected).
impl<T: Clone> Clone for InPort<T> {
    fn clone(&self) -> Self {
        let s = self.slot.borrow();
        Self {
            name: self.name,
            slot: Rc::new(RefCell::new(Slot {
                value: s.value.clone(),
                new: s.new,
            })),
        }
    }
}

impl<T> fmt::Debug for InPort<T> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.debug_struct("InPort")
            .field("name", &self.name)
            .field("is_new", &self.is_new())
            .finish()
    }
}

/// An output data port.
pub struct OutPort<T> {
    name: &'static str,
    connections: Vec<Rc<RefCell<Slot<T>>>>,
    last: Option<T>,
    writes: u64,
}

impl<T: Clone> OutPort<T> {
    /// A port with the seed's name (e.g. `Torque`).
    pub fn new(name: &'static str) -> Self {
        Self {
            name,
            connections: Vec::new(),
            last: None,
            writes: 0,
        }
    }

    /// The port's name.
    pub fn name(&self) -> &'static str {
        self.name
    }

    /// Connects this port to `input`: every later write reaches it.
    pub fn connect(&mut self, input: &InPort<T>) {
        if !self.connections.iter().any(|c| Rc::ptr_eq(c, &input.slot)) {
            self.connections.push(Rc::clone(&input.slot));
        }
    }

    /// Number of connected InPorts.
    pub fn connection_count(&self) -> usize {
        self.connections.len()
    }

    /// Sends `value` to every connected InPort and keeps it as [`OutPort::last`].
    pub fn write(&mut self, value: T) {
        for c in &self.connections {
            let mut s = c.borrow_mut();
            s.value = Some(value.clone());
            s.new = true;
        }
        self.last = Some(value);
        self.writes += 1;
    }

    /// The last value written, if any (for telemetry).
    pub fn last(&self) -> Option<&T> {
        self.last.as_ref()
    }

    /// How many writes so far.
    pub fn write_count(&self) -> u64 {
        self.writes
    }
}

/// A copy keeps the last value and the write count but is connected to nothing: the owner of
/// the copied components connects them again (a copy must not write into the original's
/// ports).
impl<T: Clone> Clone for OutPort<T> {
    fn clone(&self) -> Self {
        Self {
            name: self.name,
            connections: Vec::new(),
            last: self.last.clone(),
            writes: self.writes,
        }
    }
}

impl<T> fmt::Debug for OutPort<T> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.debug_struct("OutPort")
            .field("name", &self.name)
            .field("connections", &self.connections.len())
            .finish()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn read_clears_is_new_until_next_write() {
        let mut out = OutPort::new("Out");
        let a = InPort::new("A");
        let b = InPort::new("B");
        assert_eq!(a.read(), None::<i32>);
        out.connect(&a);
        out.connect(&b);
        out.connect(&a);
        assert_eq!(out.connection_count(), 2);
        out.write(1);
        assert!(a.is_new() && b.is_new());
        assert_eq!(a.read(), Some(1));
        assert!(!a.is_new());
        assert!(b.is_new());
        assert_eq!(a.read(), Some(1));
        out.write(2);
        assert!(a.is_new());
        assert_eq!(b.read(), Some(2));
        assert_eq!(out.last(), Some(&2));
        a.clear();
        assert!(!a.is_new());
        assert_eq!(a.read(), None);
    }

    #[test]
    fn copies_are_unconnected_and_hold_their_own_value() {
        let mut out = OutPort::new("Out");
        let a = InPort::new("A");
        out.connect(&a);
        out.write(1);
        let a2 = a.clone();
        let mut out2 = out.clone();
        assert_eq!(out2.connection_count(), 0);
        assert_eq!(out2.last(), Some(&1));
        assert!(a2.is_new());
        out.write(2);
        assert_eq!(a2.read(), Some(1));
        out2.connect(&a2);
        out2.write(3);
        assert_eq!(a.read(), Some(2));
        assert_eq!(a2.read(), Some(3));
    }
}
