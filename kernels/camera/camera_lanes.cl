/* Lane-generic body (kernels/lanes/lanes.cl): a sample's camera ray, the filter's offset
 * (filter_lanes.cl) and the ray through there (kernels/camera/camera.cl has the models; this
 * is their only code). The scalar kernels run it at W = 1 for one sample, the packet paths at
 * their width for the paths that begin together (issue 29). The camera is the same for every
 * lane, so its branches are too. */
#ifndef FACET_CAMERA_CAMERA_LANES_PASS
#define FACET_CAMERA_CAMERA_LANES_PASS

/* The unit vector along v, which is not zero (a camera's directions). */
inline LVEC3 LNAME(camera_unit)(LVEC3 v) {
    const LFLOAT inv = 1.0f / sqrt(v.x * v.x + v.y * v.y + v.z * v.z);
    return LNAME(vec3)(v.x * inv, v.y * inv, v.z * inv);
}

/* The ray through image position (x, y) in pixels, (0, 0) the top-left corner; (ux, uy) picks
 * the point on the lens. */
inline void LNAME(camera_ray)(__constant const FcCamera* cam, LFLOAT x, LFLOAT y, uint width, uint height, LFLOAT ux,
                              LFLOAT uy, LVEC3* origin, LVEC3* dir) {
    const LFLOAT sx = 2.0f * x / (float)width - 1.0f;
    const LFLOAT sy = 1.0f - 2.0f * y / (float)height;
    const float3 eye = load3c(cam->eye), forward = load3c(cam->forward), right = load3c(cam->right),
                 up = load3c(cam->up);
    if (cam->projection == FC_PROJECTION_ORTHOGRAPHIC) {
        *origin = LNAME(vec3)(eye.x + sx * right.x + sy * up.x, eye.y + sx * right.y + sy * up.y,
                              eye.z + sx * right.z + sy * up.z);
        *dir = LNAME(vec3)((LFLOAT)(forward.x), (LFLOAT)(forward.y), (LFLOAT)(forward.z));
        return;
    }
    /* at distance 1 along forward */
    const LVEC3 pinhole = LNAME(vec3)(forward.x + sx * right.x + sy * up.x, forward.y + sx * right.y + sy * up.y,
                                      forward.z + sx * right.z + sy * up.z);
    if (!(cam->lens_radius > 0.0f)) {
        *origin = LNAME(vec3)((LFLOAT)(eye.x), (LFLOAT)(eye.y), (LFLOAT)(eye.z));
        *dir = LNAME(camera_unit)(pinhole);
        return;
    }
    const float f = cam->focus_distance;
    const LVEC3 focus = LNAME(vec3)(eye.x + f * pinhole.x, eye.y + f * pinhole.y, eye.z + f * pinhole.z);
    const LVEC2 disk = LNAME(square_to_disk_concentric)(ux, uy);
    const LFLOAT lx = cam->lens_radius * disk.x, ly = cam->lens_radius * disk.y;
    const float3 rn = normalize(right), un = normalize(up); /* the same for every lane */
    const LVEC3 o =
        LNAME(vec3)(eye.x + lx * rn.x + ly * un.x, eye.y + lx * rn.y + ly * un.y, eye.z + lx * rn.z + ly * un.z);
    *origin = o;
    *dir = LNAME(camera_unit)(LNAME(vec3)(focus.x - o.x, focus.y - o.y, focus.z - o.z));
}

/* A sample's camera ray from its camera dimension set (u0, u1: the filter's point; u2, u3: the
 * lens's) at pixel (x, y): the offset the filter draws from the pixel's centre, and the ray
 * through there; returns the filter's weight (pixel_sample_ray_at of
 * kernels/camera/pixel_sample.cl). */
inline LFLOAT LNAME(pixel_sample_ray_at)(__constant const FcRenderParams* params, LFLOAT x, LFLOAT y, LFLOAT u0,
                                         LFLOAT u1, LFLOAT u2, LFLOAT u3, LVEC3* origin, LVEC3* dir) {
    LFLOAT ox, oy;
    const LFLOAT wx = LNAME(filter_sample_1d)(params->filter, params->filter_radius, u0, &ox);
    const LFLOAT wy = LNAME(filter_sample_1d)(params->filter, params->filter_radius, u1, &oy);
    LNAME(camera_ray)
    (&params->camera, x + 0.5f + ox, y + 0.5f + oy, params->width, params->height, u2, u3, origin, dir);
    return wx * wy;
}

#undef FACET_CAMERA_CAMERA_LANES_PASS
#endif
