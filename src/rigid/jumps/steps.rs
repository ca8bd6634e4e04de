//! The provisional solves of one refinement, with what their scans saw, and the
//! certificates of its ends made on that (see [`super::find_jumps`]).

use super::Refine;
use crate::gap::{GapPoint, PoseBox, Scanned};
use crate::rigid::RigidPosition;
use crate::rigid::minima::Scratch;

/// What a provisional solve's scans saw at its pose, per wheel: the scan, the pose box it
/// read (an index into [`Steps::boxes`]) and the minima found, as the solve's own
/// certificate would have read them.
#[derive(Debug, Default)]
struct Seen {
    scanned: [Scanned; 2],
    boxes: [usize; 2],
    minima: [Vec<GapPoint>; 2],
}

/// The provisional solves of one refinement in order, each with what it saw; buffers
/// reused across refinements.
#[derive(Debug, Default)]
pub(super) struct Steps {
    done: Vec<(RigidPosition, Seen)>,
    pool: Vec<Seen>,
    /// The pose boxes the steps' scans read, per wheel, each box once: the solves of a
    /// refinement, 0.1 mm of shift apart at most, mostly read one box (it holds ±1 mm), and
    /// so do the refinements of neighbouring windows. Kept across refinements (the last box
    /// of each wheel), so that the certificates' cushions made in a box serve every
    /// certificate read against it, instead of each step's copy of the box making them
    /// again, and a box is copied once instead of at each step.
    boxes: Vec<(usize, PoseBox)>,
    box_pool: Vec<PoseBox>,
}

impl Steps {
    pub(super) fn clear(&mut self) {
        self.pool.extend(self.done.drain(..).map(|(_, seen)| seen));
        // The last box of each wheel stays: the next refinement's first solves most often
        // read it again.
        let mut kept = 0;
        for i in 0..self.boxes.len() {
            let w = self.boxes[i].0;
            if self.boxes[i + 1..].iter().all(|(v, _)| *v != w) {
                self.boxes.swap(kept, i);
                kept += 1;
            }
        }
        self.box_pool
            .extend(self.boxes.drain(kept..).map(|(_, pose_box)| pose_box));
    }

    pub(super) fn len(&self) -> usize {
        self.done.len()
    }

    /// The positions of the first `n` steps.
    pub(super) fn positions(&self, n: usize) -> Vec<RigidPosition> {
        self.done[..n].iter().map(|(p, _)| *p).collect()
    }

    /// Records a provisional solve `p` with what its scans saw for `wheels`, taken from
    /// `scratch` (the scans are swapped: each keeps its own count of scans, so a buffer
    /// handed back to the solver stays consistent; the pose box is copied where it is not
    /// kept already); the step's index.
    pub(super) fn push(
        &mut self,
        p: RigidPosition,
        scratch: &mut Scratch,
        wheels: &[usize],
    ) -> usize {
        let mut seen = self.pool.pop().unwrap_or_default();
        for &w in wheels {
            std::mem::swap(&mut seen.scanned[w], &mut scratch.scanned[w]);
            seen.boxes[w] = self.box_index(w, &scratch.boxes[w]);
            seen.minima[w].clone_from(&scratch.minima[w]);
        }
        self.done.push((p, seen));
        self.done.len() - 1
    }

    /// The index in [`Steps::boxes`] of wheel `w`'s box `current`, copied there if it is
    /// not yet.
    fn box_index(&mut self, w: usize, current: &PoseBox) -> usize {
        let same = |(v, b): &(usize, PoseBox)| *v == w && b.made_at_same_pose(current);
        if let Some(i) = self.boxes.iter().rposition(same) {
            return i;
        }
        let mut pose_box = self.box_pool.pop().unwrap_or_default();
        pose_box.clone_from(current);
        self.boxes.push((w, pose_box));
        self.boxes.len() - 1
    }

    /// Whether step `i` holds the global minima of `wheels`: the certificate
    /// (`gap::certify`) finds no point lower than the contact by more than its tolerance,
    /// so that a certified solve gives the same position. It reads what the solve's scan
    /// saw at the step's pose, with the minima the solve found, as the solve's own
    /// certificate would have; a solve that stopped on a pose it did not scan (an
    /// iteration cap) is scanned again.
    pub(super) fn certified<'a>(
        &mut self,
        solver: &mut impl Refine<'a>,
        i: usize,
        wheels: &[usize],
    ) -> bool {
        let (p, seen) = &mut self.done[i];
        let boxes = &mut self.boxes;
        let sides = solver.sides_at(p.y_ws);
        wheels.iter().all(|&w| {
            let (side, Some(c)) = (&sides[w], p.contact[w]) else {
                return true;
            };
            let pose = side.pose(p.y_ws, p.roll);
            let minima = &seen.minima[w];
            let found = minima.iter().find(|m| m.s.to_bits() == c.s.to_bits());
            let Some(best) = found.copied().or_else(|| side.at(c.s, &pose)) else {
                return false;
            };
            let certificate = if seen.scanned[w].pose() == Some(pose) {
                let (pose_box, scanned) = (&mut boxes[seen.boxes[w]].1, &mut seen.scanned[w]);
                side.certify_scanned(&pose, best, minima, pose_box, scanned)
            } else {
                side.certify(&pose, best, &[best])
            };
            certificate.lower.is_none()
        })
    }
}
