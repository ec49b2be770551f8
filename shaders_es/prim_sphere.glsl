// First crossing of segment a -> b (t in [0, 1]) with a sphere; a segment starting inside hits where
// it leaves. Same contract as intersect_sphere() in src/physics/intersect.c.
bool hit_sphere(vec3 a, vec3 b, vec3 c, float radius, out float t)
{
    t = 0.0;
    vec3 d = b - a;
    vec3 oc = a - c;
    float dd = dot(d, d);
    if (dd <= 0.0)
        return false;
    float half_b = dot(oc, d);
    // radius^2 minus the squared distance of the line from c: no cancellation of two large squares.
    vec3 closest = oc - (half_b / dd) * d;
    float disc = radius * radius - dot(closest, closest);
    if (disc < 0.0)
        return false;
    float root = sqrt(dd * disc);
    float q = -(half_b + (half_b < 0.0 ? -root : root));
    float t_near = 0.0;
    float t_far = 0.0;
    if (q != 0.0) {
        // Vieta's product keeps the smaller root accurate where -b + sqrt would cancel.
        float t1 = q / dd;
        float t2 = (dot(oc, oc) - radius * radius) / q;
        t_near = min(t1, t2);
        t_far = max(t1, t2);
    }
    if (t_near >= 0.0 && t_near <= 1.0) {
        t = t_near;
        return true;
    }
    if (t_far >= 0.0 && t_far <= 1.0) {
        t = t_far;
        return true;
    }
    return false;
}
