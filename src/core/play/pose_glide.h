/* aero: the path of a posed body between its poses, and the queue that
 * applies poses at their time within a block. Shared by [aeolian~]'s
 * texture mode (a stick's two ends) and [body~] (a position and a
 * quaternion).
 *
 * The path is C1 (position and velocity continuous): at each new pose a
 * cubic Hermite segment runs from where the path is, with its velocity,
 * to the pose over the pose's interval, arriving with the stream's
 * velocity there: the tangent from the last two chords ((new - previous
 * pose) / interval, and the one before: a second-order backward
 * difference, exact for a constant acceleration), the chord alone after
 * a pause. Past the pose the path goes on at that velocity for half an
 * interval (a pose due now may come late), then slows on a half cosine
 * to rest at two intervals (a stream that ends stops without a step of
 * the velocity or its slope). The path lags the stream by one interval.
 * Why: a polyline through the poses steps the velocity, hence the
 * Doppler rate, at every pose, a click each time at the speed of a
 * whirled sword's tip (a whirled sine's click measure 12.7, against 3.8
 * posed every 64 samples); arriving with the chord's velocity instead of
 * the tangent leaves the acceleration stepping at each pose (up to 4,
 * where the tangent gives 1.4-1.9: tests/unit/test_aeolian_texture.c,
 * whirl_without_clicks).
 *
 * Host-independent C99, no globals. Times in samples. */
#ifndef AERO_POSE_GLIDE_H
#define AERO_POSE_GLIDE_H

#define AERO_GLIDE_DIM_MAX 7 /* a body's position and quaternion */
#define AERO_GLIDE_QUEUE 8   /* poses waiting for their sample */
#define AERO_GLIDE_EVENT_MAX 10

typedef struct {
    int dim;
    double pos[AERO_GLIDE_DIM_MAX];  /* on the path now */
    double vel[AERO_GLIDE_DIM_MAX];  /* its derivative, per sample */
    double from[AERO_GLIDE_DIM_MAX], from_vel[AERO_GLIDE_DIM_MAX];
    double to[AERO_GLIDE_DIM_MAX];   /* the last pose */
    double to_vel[AERO_GLIDE_DIM_MAX]; /* the stream's velocity at `to` */
    double elapsed, duration;        /* since the last pose; its interval */
    double chord[AERO_GLIDE_DIM_MAX]; /* (to - the pose before) / interval */
    int after_standing;              /* the segment began with the path
                                        standing (after a jump) */
} aero_pose_path;

/* the path stands at x (the first pose, a placement, a new gesture) */
void aero_pose_path_jump(aero_pose_path *p, int dim, const double *x);
/* a new pose x, interval samples after the previous one (> 0) */
void aero_pose_path_to(aero_pose_path *p, const double *x, double interval);
/* moves the path on by m samples: pos and vel at the new time */
void aero_pose_path_advance(aero_pose_path *p, double m);
/* 1 when the stream has ended: the path came to rest two intervals after
 * its last pose. A pose after that begins a new gesture (the players jump
 * to it): the path lags the stream by one interval, so gliding there over
 * the pause and then catching up in one interval crossed the pause's
 * whole way in a pose's interval, near Mach 1 for a sword after 0.3 s (a
 * Doppler burst, click measure 7-330, issue 48). */
int aero_pose_path_ended(const aero_pose_path *p);
/* 1 when a pose `interval` samples after the last is the first of a
 * gesture that began at the last pose: the running segment is the first
 * after the path stood (placed, or a new gesture) and lasts more than
 * twice the new interval, a wait and not a motion (a pose 0.2 s after a
 * placement, then one every 5 ms). The players jump to the last pose and
 * glide on from there: the path catching up a 0.2 s segment in 5 ms was a
 * Doppler burst (click measure 935, issue 48). */
int aero_pose_path_waited(const aero_pose_path *p, double interval);
/* the fraction of the stream's velocity the path keeps now: 1 up to 1.5
 * intervals, falling to 0 as it comes to rest (0 standing: placed, or
 * never posed) */
double aero_pose_path_pace(const aero_pose_path *p);

/* a pose waiting for its sample: the numbers the player applies, its
 * interval (s, < 0 a placement) and its sample in the next block */
typedef struct {
    double x[AERO_GLIDE_EVENT_MAX];
    int has_extra;      /* x holds an optional part (the stick's axis) */
    double interval_s;
    int offset;
} aero_pose_event;

typedef struct {
    aero_pose_event ev[AERO_GLIDE_QUEUE];
    int head, n;
} aero_pose_queue;

/* queues e (its offset made >= 0 and >= the last queued one's). Full:
 * the oldest is moved to *oldest and 1 is returned (the caller applies
 * it at once), else 0. */
int aero_pose_queue_push(aero_pose_queue *q, const aero_pose_event *e,
                         aero_pose_event *oldest);
/* the first queued pose, or NULL */
const aero_pose_event *aero_pose_queue_front(const aero_pose_queue *q);
/* the last queued pose, or NULL */
const aero_pose_event *aero_pose_queue_back(const aero_pose_queue *q);
void aero_pose_queue_pop(aero_pose_queue *q);
/* samples from `done` to the first pose's offset, at most m; 0 when the
 * first pose is due now */
int aero_pose_queue_until(const aero_pose_queue *q, int done, int m);
/* a process call of n samples is over: the poses beyond it come n samples
 * sooner in the next (a block smaller than the host's tick: Pd calls
 * perform several times at one logical time) */
void aero_pose_queue_elapse(aero_pose_queue *q, int n);

#endif
