//! Data ports: `OutPort<T>` writes to every connected `InPort<T>` (spec §1 "Ports").
//!
//! Each connection has a [`Connector`]: the system's handle on it, which counts the samples
//! it carried and can cut it (no sample passes until it is restored), as RT System Editor
//! deletes and re-creates a connector.
//!
//! **Decision**: an InPort holds the newest value only (OpenRTM's buffer of length one with
//! overwrite), which is what the seeds' `isNew()` / `read()` pattern needs. Ports are
//! single-threaded (`Rc<RefCell<…>>`): the whole system runs in one execution context.

use std::cell::{Cell, RefCell};
use std::fmt;
use std::rc::Rc;

use super::sample::{PortDirection, PortView, Sample, SampleView};

#[derive(Debug)]
struct Slot<T> {
    value: Option<T>,
    new: bool,
    /// Samples written into it so far.
    received: u64,
}

#[derive(Debug, Default)]
struct Gate {
    cut: Cell<bool>,
    carried: Cell<u64>,
}

/// The handle on one connection `OutPort → InPort` ([`OutPort::connect`]): how many samples
/// it carried, and whether it is cut.
#[derive(Debug, Clone)]
pub struct Connector(Rc<Gate>);

impl Connector {
    /// Samples that went through it.
    pub fn carried(&self) -> u64 {
        self.0.carried.get()
    }

    /// Whether it is cut: the out-port's writes do not reach the in-port.
    pub fn is_cut(&self) -> bool {
        self.0.cut.get()
    }

    /// Cuts it (`true`) or restores it (`false`).
    pub fn set_cut(&self, cut: bool) {
        self.0.cut.set(cut);
    }

    /// Takes over `other`'s count and cut (the same connection in a copied system).
    pub fn copy_state_from(&self, other: &Connector) {
        self.0.cut.set(other.is_cut());
        self.0.carried.set(other.carried());
    }
}

struct Link<T> {
    slot: Rc<RefCell<Slot<T>>>,
    gate: Connector,
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
                received: 0,
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
        s.received += 1;
    }

    /// Samples received so far.
    pub fn received_count(&self) -> u64 {
        self.slot.borrow().received
    }
}

impl<T: Sample> InPort<T> {
    /// The port as RT System Editor shows it, with its newest sample (read or not).
    pub fn view(&self) -> PortView {
        let s = self.slot.borrow();
        PortView {
            name: self.name,
            direction: PortDirection::In,
            idl: T::IDL,
            count: s.received,
            last: s.value.as_ref().map(SampleView::of),
        }
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
                received: s.received,
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
    connections: Vec<Link<T>>,
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

    /// Connects this port to `input`: every later write reaches it (while the connection is
    /// not cut). Returns the connection's handle (the same one if they were connected).
    pub fn connect(&mut self, input: &InPort<T>) -> Connector {
        if let Some(link) = self
            .connections
            .iter()
            .find(|c| Rc::ptr_eq(&c.slot, &input.slot))
        {
            return link.gate.clone();
        }
        let gate = Connector(Rc::new(Gate::default()));
        self.connections.push(Link {
            slot: Rc::clone(&input.slot),
            gate: gate.clone(),
        });
        gate
    }

    /// Drops every connection (the component at the other end is being replaced; the owner
    /// connects the port again).
    pub fn disconnect_all(&mut self) {
        self.connections.clear();
    }

    /// Number of connected InPorts.
    pub fn connection_count(&self) -> usize {
        self.connections.len()
    }

    /// Sends `value` to every connected InPort (but through a cut connection) and keeps it
    /// as [`OutPort::last`].
    pub fn write(&mut self, value: T) {
        for c in &self.connections {
            if c.gate.is_cut() {
                continue;
            }
            let mut s = c.slot.borrow_mut();
            s.value = Some(value.clone());
            s.new = true;
            s.received += 1;
            c.gate.0.carried.set(c.gate.carried() + 1);
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

impl<T: Clone + Sample> OutPort<T> {
    /// The port as RT System Editor shows it, with the last sample written.
    pub fn view(&self) -> PortView {
        PortView {
            name: self.name,
            direction: PortDirection::Out,
            idl: T::IDL,
            count: self.writes,
            last: self.last.as_ref().map(SampleView::of),
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

    #[test]
    fn a_cut_connection_carries_nothing_until_restored() {
        let mut out = OutPort::new("Out");
        let a = InPort::new("A");
        let b = InPort::new("B");
        let to_a = out.connect(&a);
        let to_b = out.connect(&b);
        assert_eq!(out.connect(&a).carried(), 0);
        out.write(1);
        to_a.set_cut(true);
        out.write(2);
        assert_eq!((a.read(), b.read()), (Some(1), Some(2)));
        assert_eq!((to_a.carried(), to_b.carried()), (1, 2));
        assert_eq!((a.received_count(), b.received_count()), (1, 2));
        to_a.set_cut(false);
        out.write(3);
        assert_eq!(a.read(), Some(3));
        assert_eq!(to_a.carried(), 2);
        assert!(!to_a.is_cut());
    }
}
