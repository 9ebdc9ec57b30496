//! What a drawing call did: the primitives looked at, those dropped and why, and what was
//! drawn. Below the pipeline and the buffers, which both count into it.

/// What one drawing call did. Counts saturate. Drawing a frame band by band gives every band
/// the same `primitives`, `invalid`, `outside`, `clipped`, `culled` and `degenerate` counts;
/// `drawn`, `carried`, `fragments` and `written` are that band's.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub struct Stats {
    /// Triangles (or edges, for wireframes with an edge list) looked at.
    pub primitives: u32,
    /// Dropped: an index refers to no vertex.
    pub invalid: u32,
    /// Dropped: entirely outside the near plane, the far plane or the guard band.
    pub outside: u32,
    /// Went through homogeneous clipping (crossing the near/far plane or the guard band).
    pub clipped: u32,
    /// Dropped by back-face culling.
    pub culled: u32,
    /// Dropped: zero area after snapping.
    pub degenerate: u32,
    /// Triangles (or lines) handed to the rasteriser.
    pub drawn: u32,
    /// Of those, triangles a band took on from where the band before stopped them, with no
    /// set-up (see [`Carries`](crate::buffer::Carries)).
    pub carried: u32,
    /// Pixels depth-tested (or drawn, without depth).
    pub fragments: u32,
    /// Pixels written.
    pub written: u32,
}

impl core::ops::Add for Stats {
    type Output = Stats;

    /// Both counts of each kind, saturating.
    fn add(self, o: Stats) -> Stats {
        let add = |a: u32, b: u32| a.saturating_add(b);
        Stats {
            primitives: add(self.primitives, o.primitives),
            invalid: add(self.invalid, o.invalid),
            outside: add(self.outside, o.outside),
            clipped: add(self.clipped, o.clipped),
            culled: add(self.culled, o.culled),
            degenerate: add(self.degenerate, o.degenerate),
            drawn: add(self.drawn, o.drawn),
            carried: add(self.carried, o.carried),
            fragments: add(self.fragments, o.fragments),
            written: add(self.written, o.written),
        }
    }
}
