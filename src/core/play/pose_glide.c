/* aero: a C1 path through poses and the queue of poses within a block
 * (see pose_glide.h). */
#include "pose_glide.h"

#include <math.h>
#include <string.h>

#define AERO_GLIDE_PI 3.14159265358979323846

void aero_pose_path_jump(aero_pose_path *p, int dim, const double *x)
{
    memset(p, 0, sizeof(*p));
    p->dim = dim < 1 ? 1 : dim > AERO_GLIDE_DIM_MAX ? AERO_GLIDE_DIM_MAX : dim;
    for (int i = 0; i < p->dim; i++)
        p->pos[i] = p->from[i] = p->to[i] = x[i];
}

void aero_pose_path_to(aero_pose_path *p, const double *x, double interval)
{
    if (!(interval >= 1.0))
        interval = 1.0;
    /* the stream was moving (its last chord is of this motion, not from
       before a pause): the tangent at x from the last two chords */
    int moving = p->duration > 0.0 && interval <= 1.5 * p->duration;
    double weight = moving ? interval / (interval + p->duration) : 0.0;
    for (int i = 0; i < p->dim; i++) {
        double chord = (x[i] - p->to[i]) / interval;
        p->to_vel[i] = chord + weight * (chord - p->chord[i]);
        p->chord[i] = chord;
        p->from[i] = p->pos[i];
        p->from_vel[i] = p->vel[i];
        p->to[i] = x[i];
    }
    p->after_standing = !(p->duration > 0.0);
    p->elapsed = 0.0;
    p->duration = interval;
}

void aero_pose_path_advance(aero_pose_path *p, double m)
{
    const double T = p->duration;
    p->elapsed += m;
    if (!(T > 0.0)) { /* no motion yet */
        for (int i = 0; i < p->dim; i++) {
            p->pos[i] = p->to[i];
            p->vel[i] = 0.0;
        }
        return;
    }
    double t = p->elapsed;
    if (t <= T) { /* the Hermite segment */
        double s = t / T, s2 = s * s, s3 = s2 * s;
        double h00 = 2.0 * s3 - 3.0 * s2 + 1.0, h10 = s3 - 2.0 * s2 + s,
               h01 = 3.0 * s2 - 2.0 * s3, h11 = s3 - s2;
        double d00 = (6.0 * s2 - 6.0 * s) / T, d10 = 3.0 * s2 - 4.0 * s + 1.0,
               d11 = 3.0 * s2 - 2.0 * s;
        for (int i = 0; i < p->dim; i++) {
            p->pos[i] = h00 * p->from[i] + h10 * T * p->from_vel[i] +
                        h01 * p->to[i] + h11 * T * p->to_vel[i];
            p->vel[i] = d00 * (p->from[i] - p->to[i]) +
                        d10 * p->from_vel[i] + d11 * p->to_vel[i];
        }
        return;
    }
    /* on past the pose at that velocity for half an interval (a pose due
       now may come late), then slowing to rest at two intervals on a half
       cosine: a stream that ends stops without a step of the velocity or
       of the acceleration (slowing evenly stepped the Doppler rate's slope
       at both ends: a whirled sine's stop measured 3.7, issue 48) */
    double past = t - T, on = past < 0.5 * T ? past : 0.5 * T;
    double slow = past > 0.5 * T ? (past < T ? past : T) - 0.5 * T : 0.0;
    double phase = 2.0 * AERO_GLIDE_PI * slow / T;
    double keep = 0.5 + 0.5 * cos(phase);
    double gone = 0.5 * slow + T / (4.0 * AERO_GLIDE_PI) * sin(phase);
    for (int i = 0; i < p->dim; i++) {
        p->pos[i] = p->to[i] + (on + gone) * p->to_vel[i];
        p->vel[i] = keep * p->to_vel[i];
    }
}

int aero_pose_path_ended(const aero_pose_path *p)
{
    return p->duration > 0.0 && p->elapsed >= 2.0 * p->duration;
}

int aero_pose_path_waited(const aero_pose_path *p, double interval)
{
    return p->after_standing && p->duration > 2.0 * interval;
}

double aero_pose_path_pace(const aero_pose_path *p)
{
    const double T = p->duration;
    if (!(T > 0.0) || p->elapsed >= 2.0 * T)
        return 0.0;
    return p->elapsed <= 1.5 * T
               ? 1.0
               : 0.5 + 0.5 * cos(2.0 * AERO_GLIDE_PI * (p->elapsed - 1.5 * T) / T);
}

/* --- the queue ------------------------------------------------------------ */

static aero_pose_event *slot(aero_pose_queue *q, int k)
{
    return &q->ev[(q->head + k) % AERO_GLIDE_QUEUE];
}

int aero_pose_queue_push(aero_pose_queue *q, const aero_pose_event *e,
                         aero_pose_event *oldest)
{
    int full = q->n == AERO_GLIDE_QUEUE;
    if (full) {
        *oldest = *slot(q, 0);
        aero_pose_queue_pop(q);
    }
    aero_pose_event *to = slot(q, q->n);
    *to = *e;
    if (!(to->offset >= 0))
        to->offset = 0;
    if (q->n > 0 && to->offset < slot(q, q->n - 1)->offset)
        to->offset = slot(q, q->n - 1)->offset; /* in the order given */
    q->n++;
    return full;
}

const aero_pose_event *aero_pose_queue_front(const aero_pose_queue *q)
{
    return q->n > 0 ? &q->ev[q->head] : NULL;
}

const aero_pose_event *aero_pose_queue_back(const aero_pose_queue *q)
{
    return q->n > 0 ? &q->ev[(q->head + q->n - 1) % AERO_GLIDE_QUEUE] : NULL;
}

void aero_pose_queue_pop(aero_pose_queue *q)
{
    if (q->n <= 0)
        return;
    q->head = (q->head + 1) % AERO_GLIDE_QUEUE;
    q->n--;
}

int aero_pose_queue_until(const aero_pose_queue *q, int done, int m)
{
    if (q->n <= 0)
        return m;
    int left = q->ev[q->head].offset - done;
    return left <= 0 ? 0 : left < m ? left : m;
}

void aero_pose_queue_elapse(aero_pose_queue *q, int n)
{
    for (int k = 0; k < q->n; k++) {
        aero_pose_event *e = slot(q, k);
        e->offset = e->offset > n ? e->offset - n : 0;
    }
}
