//! Rays with a valid parameter range, and robust origins for rays that leave a surface.

use lobe::Vec3;

/// A ray `o + t d` whose valid hits lie in `t_min < t < t_max` (seed 003: "a class called
/// Ray … point and direction; evaluate(t); tMin, tMax").
#[derive(Clone, Copy, Debug)]
pub struct Ray {
    /// The origin.
    pub origin: Vec3,
    /// The direction; unit length everywhere in this renderer.
    pub dir: Vec3,
    /// The smallest valid `t` (exclusive).
    pub t_min: f32,
    /// The largest valid `t` (exclusive); `f32::INFINITY` for an unbounded ray.
    pub t_max: f32,
}

impl Ray {
    /// An unbounded ray from `origin` along the unit direction `dir`.
    pub fn new(origin: Vec3, dir: Vec3) -> Self {
        Self {
            origin,
            dir,
            t_min: 0.0,
            t_max: f32::INFINITY,
        }
    }

    /// A ray from `origin` along `dir` that stops short of `t_max` (a shadow ray).
    pub fn segment(origin: Vec3, dir: Vec3, t_max: f32) -> Self {
        Self {
            origin,
            dir,
            t_min: 0.0,
            t_max,
        }
    }

    /// The point at parameter `t`.
    #[inline]
    pub fn at(&self, t: f32) -> Vec3 {
        self.origin + self.dir * t
    }

    /// True when `t` is inside the valid range.
    #[inline]
    pub fn contains(&self, t: f32) -> bool {
        t > self.t_min && t < self.t_max
    }
}

/// The distance by which a ray's origin is pushed off a surface at `p`: a relative bound on
/// the floating-point error of a computed hit point, `1e-4 (1 + max |p_i|)` (a simplified
/// form of pbrt's error bounds, PBR 4th ed. §6.8): it grows with the magnitude of the
/// coordinates, so that it works for a scene at any scale and far from the origin, where a
/// fixed epsilon fails.
#[inline]
pub fn offset_scale(p: Vec3) -> f32 {
    1e-4 * (1.0 + p.abs().max_element())
}

/// The origin of a ray leaving the surface point `p` (geometric normal `ng`) in direction
/// `w`: `p` pushed along `ng` by [`offset_scale`], on the side `w` points to, so that the new
/// ray cannot hit the surface it starts from.
#[inline]
pub fn offset_origin(p: Vec3, ng: Vec3, w: Vec3) -> Vec3 {
    let d = offset_scale(p);
    if w.dot(ng) >= 0.0 {
        p + ng * d
    } else {
        p - ng * d
    }
}

/// A shadow ray from the surface point `p` (geometric normal `ng`) to the point `q`, on a
/// light's surface of normal `nq` (`None` for a point light).
///
/// Both ends are offset off their surfaces, each toward the other end, and the ray runs
/// between the offset points: it passes exactly through the offset target, so that neither
/// the surface it starts from nor the light's own surface can occlude it. (Pulling the end
/// in along a ray aimed from the un-offset `p` is not enough: near a sphere light's rim
/// that ray enters the sphere before the target, and 0.8% of the light went missing.)
/// `None` when the two points coincide.
pub fn shadow_ray(p: Vec3, ng: Vec3, q: Vec3, nq: Option<Vec3>) -> Option<Ray> {
    if !(p.distance_squared(q) > 0.0) {
        return None;
    }
    let origin = offset_origin(p, ng, q - p);
    let target = match nq {
        Some(n) => offset_origin(q, n, origin - q),
        None => q,
    };
    let to = target - origin;
    let dist = to.length();
    if !(dist > 0.0) || !dist.is_finite() {
        return None;
    }
    Some(Ray::segment(origin, to / dist, dist))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn offset_grows_with_the_coordinates_and_picks_the_side() {
        let n = Vec3::Y;
        let near = offset_origin(Vec3::ZERO, n, Vec3::Y);
        let far = offset_origin(Vec3::new(1e4, 0.0, 0.0), n, -Vec3::Y);
        assert!(near.y > 0.0);
        assert!(far.y < 0.0);
        assert!(-far.y > 100.0 * near.y);
    }

    #[test]
    fn shadow_ray_stops_short_of_its_target() {
        let q = Vec3::new(0.0, 2.0, 0.0);
        let r = shadow_ray(Vec3::ZERO, Vec3::Y, q, Some(-Vec3::Y)).unwrap();
        assert!(r.t_max < 2.0 && r.t_max > 1.99);
        assert!(r.at(r.t_max).y < 2.0);
        let to_point = shadow_ray(Vec3::ZERO, Vec3::Y, q, None).unwrap();
        assert!((to_point.at(to_point.t_max) - q).length() < 1e-6);
        assert!(shadow_ray(Vec3::ONE, Vec3::Y, Vec3::ONE, None).is_none());
    }
}
