//! [`Group`]: a set of surfaces behind a bounding volume hierarchy.

use crate::aabb::Aabb;
use crate::ray::Ray;
use crate::surface::{Hit, Surface};
use lobe::Vec3;

/// The most surfaces in a leaf.
const LEAF_SIZE: usize = 2;
/// The deepest traversal stack; the median split keeps the depth near `log2(n)`.
const STACK: usize = 64;

/// A node of the flattened tree: a leaf holds `count > 0` surfaces from `first`; an inner
/// node's children are at `index + 1` and `first` (the second child).
#[derive(Clone, Copy, Debug)]
struct Node {
    /// The box around everything below the node.
    bounds: Aabb,
    /// A leaf's first surface, or an inner node's second child.
    first: u32,
    /// A leaf's number of surfaces; `0` for an inner node.
    count: u32,
    /// The axis of the split, used to visit the nearer child first.
    axis: u8,
}

/// A group of surfaces that is itself a [`Surface`] (seed 003: "groups of surfaces
/// (acceleration goes here)"), accelerated by a binary BVH built by median splits along the
/// widest axis of the centroids.
pub struct Group {
    /// The surfaces, in the order of the leaves.
    surfaces: Vec<Box<dyn Surface>>,
    /// The flattened tree, root first.
    nodes: Vec<Node>,
}

impl Group {
    /// The group of `surfaces`, with its BVH built.
    pub fn new(mut surfaces: Vec<Box<dyn Surface>>) -> Self {
        let mut nodes = Vec::with_capacity(2 * surfaces.len().max(1));
        if !surfaces.is_empty() {
            let n = surfaces.len();
            build(&mut surfaces, 0, n, &mut nodes);
        }
        Self { surfaces, nodes }
    }

    /// The number of surfaces directly in the group.
    #[cfg(test)]
    pub fn len(&self) -> usize {
        self.surfaces.len()
    }

    /// Visits the leaves whose boxes the ray meets, nearer children first, calling `leaf` on
    /// each surface; `leaf` returns the new `t_max` (it shrinks as closer hits are found), or
    /// `None` to stop the traversal.
    #[inline]
    fn traverse(&self, ray: &Ray, mut leaf: impl FnMut(&dyn Surface, f32) -> Option<f32>) {
        if self.nodes.is_empty() {
            return;
        }
        let inv_dir = Vec3::ONE / ray.dir;
        let negative = [ray.dir.x < 0.0, ray.dir.y < 0.0, ray.dir.z < 0.0];
        let mut t_max = ray.t_max;
        let mut stack = [0u32; STACK];
        let mut top = 1;
        while top > 0 {
            top -= 1;
            let node = &self.nodes[stack[top] as usize];
            if !node.bounds.hit(ray.origin, inv_dir, ray.t_min, t_max) {
                continue;
            }
            if node.count > 0 {
                let start = node.first as usize;
                for s in &self.surfaces[start..start + node.count as usize] {
                    match leaf(s.as_ref(), t_max) {
                        Some(t) => t_max = t,
                        None => return,
                    }
                }
            } else if top + 2 <= STACK {
                let index = stack[top] + 1;
                let (near, far) = if negative[node.axis as usize] {
                    (node.first, index)
                } else {
                    (index, node.first)
                };
                stack[top] = far;
                stack[top + 1] = near;
                top += 2;
            }
        }
    }
}

/// Builds the subtree over `surfaces[start..end]`, appending its nodes; returns its index.
fn build(
    surfaces: &mut [Box<dyn Surface>],
    start: usize,
    end: usize,
    nodes: &mut Vec<Node>,
) -> usize {
    let bounds = surfaces[start..end]
        .iter()
        .fold(Aabb::EMPTY, |b, s| b.union(s.bounds()));
    let index = nodes.len();
    nodes.push(Node {
        bounds,
        first: start as u32,
        count: (end - start) as u32,
        axis: 0,
    });
    if end - start <= LEAF_SIZE {
        return index;
    }
    let centroids = surfaces[start..end].iter().fold(Aabb::EMPTY, |b, s| {
        let c = s.bounds().centroid();
        b.union(Aabb { min: c, max: c })
    });
    let extent = centroids.max - centroids.min;
    let axis = if extent.x >= extent.y && extent.x >= extent.z {
        0
    } else if extent.y >= extent.z {
        1
    } else {
        2
    };
    let mid = start + (end - start) / 2;
    surfaces[start..end].select_nth_unstable_by(mid - start, |a, b| {
        a.bounds().centroid()[axis].total_cmp(&b.bounds().centroid()[axis])
    });
    build(surfaces, start, mid, nodes);
    let second = build(surfaces, mid, end, nodes);
    nodes[index].first = second as u32;
    nodes[index].count = 0;
    nodes[index].axis = axis as u8;
    index
}

impl Surface for Group {
    fn intersect(&self, ray: &Ray) -> Option<Hit> {
        let mut closest: Option<Hit> = None;
        self.traverse(ray, |s, t_max| {
            let r = Ray { t_max, ..*ray };
            Some(match s.intersect(&r) {
                Some(h) => {
                    closest = Some(h);
                    h.t
                }
                None => t_max,
            })
        });
        closest
    }

    fn occluded(&self, ray: &Ray) -> bool {
        let mut blocked = false;
        self.traverse(ray, |s, t_max| {
            if s.occluded(ray) {
                blocked = true;
                None
            } else {
                Some(t_max)
            }
        });
        blocked
    }

    fn bounds(&self) -> Aabb {
        self.nodes.first().map_or(Aabb::EMPTY, |n| n.bounds)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::sphere::Sphere;

    /// The BVH finds the same closest hit as a linear scan.
    #[test]
    fn matches_a_linear_scan() {
        let mut spheres = Vec::new();
        for i in 0..40 {
            let x = (i % 7) as f32 * 1.3 - 4.0;
            let y = (i / 7) as f32 * 1.1 - 3.0;
            let z = ((i * 37) % 11) as f32 * 0.7;
            spheres.push(Sphere::new(Vec3::new(x, y, z), 0.4 + 0.02 * i as f32, i));
        }
        let group = Group::new(
            spheres
                .iter()
                .map(|s| Box::new(*s) as Box<dyn Surface>)
                .collect(),
        );
        assert_eq!(group.len(), 40);
        let mut hits = 0;
        for i in 0..400 {
            let a = i as f32 * 0.618_034;
            let dir = Vec3::new(a.sin() * 0.5, (a * 1.7).cos() * 0.5, 1.0).normalize();
            let ray = Ray::new(Vec3::new(0.0, 0.0, -10.0), dir);
            let linear = spheres
                .iter()
                .filter_map(|s| s.intersect(&ray))
                .min_by(|a, b| a.t.total_cmp(&b.t));
            let bvh = group.intersect(&ray);
            assert_eq!(linear.map(|h| h.material), bvh.map(|h| h.material));
            assert_eq!(linear.is_some(), group.occluded(&ray));
            hits += usize::from(bvh.is_some());
        }
        assert!(hits > 50, "the test rays hit something ({hits})");
    }
}
