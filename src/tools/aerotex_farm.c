/* aerotex: the task farm over MPI ranks and its checkpoint (aerotex.h).
 *
 * A texture's directions, sections and speeds are independent
 * simulations: rank r of N runs the tasks k with k % N == r (its threads
 * inside, as one process does), rank 0 gathers them with MPI_Gatherv
 * and writes the texture. Each task is a deterministic function of the
 * command line and its index (its seed is aero_run_seed(seed, k), the
 * solvers' results do not depend on their thread count), so the texture
 * is the one-process texture sample for sample.
 *
 * The checkpoint: every finished task in OUT.ckpt/taskNNNN.bin (written
 * to a temporary name, then renamed, so a kill leaves whole files only),
 * stamped with a hash of the command line; a job run again with the same
 * command line loads them instead of running them, whatever its number
 * of ranks. Only in the MPI build (a cluster's scheduler preempts jobs);
 * the plain build has neither. */
#include "aerotex.h"

#include <stdint.h>
#include <string.h>

#ifdef AEROTEX_MPI
#include <mpi.h>

#include <errno.h>
#include <limits.h>
#include <stdio.h>
#include <stdlib.h>
#include <time.h>
#include <unistd.h>

void aerotex_farm_init(int *argc, char ***argv)
{
    int provided;
    MPI_Init_thread(argc, argv, MPI_THREAD_FUNNELED, &provided);
}

void aerotex_farm_finalize(void)
{
    MPI_Finalize();
}

int aerotex_farm_rank(void)
{
    int r;
    MPI_Comm_rank(MPI_COMM_WORLD, &r);
    return r;
}

int aerotex_farm_size(void)
{
    int n;
    MPI_Comm_size(MPI_COMM_WORLD, &n);
    return n;
}

/* --- the checkpoint -------------------------------------------------------- */

#define CKPT_MAGIC "AEROCKP1"

typedef struct {
    char magic[8];
    uint64_t command; /* FNV-1a of the command line */
    uint64_t task_size, frames, width, channels, index;
} ckpt_header;

static uint64_t fnv1a(const char *s)
{
    uint64_t h = 14695981039346656037u;
    for (; *s; s++)
        h = (h ^ (unsigned char)*s) * 1099511628211u;
    return h;
}

static ckpt_header header(const aerotex_job *j, int k, size_t task_size,
                          int width)
{
    ckpt_header h;
    memset(&h, 0, sizeof h);
    memcpy(h.magic, CKPT_MAGIC, 8);
    h.command = fnv1a(j->command);
    h.task_size = task_size;
    h.frames = (uint64_t)j->loop.avail;
    h.width = (uint64_t)width;
    h.channels = (uint64_t)j->channels;
    h.index = (uint64_t)k;
    return h;
}

/* OUT.ckpt, or with k >= 0 OUT.ckpt/taskNNNN.bin */
static void ckpt_path(char *buf, size_t len, const aerotex_job *j, int k)
{
    if (k < 0)
        snprintf(buf, len, "%s.ckpt", j->out);
    else
        snprintf(buf, len, "%s.ckpt/task%04d.bin", j->out, k);
}

/* OUT.ckpt/stateNNNN.bin: a running task's solver state */
static void state_path(char *buf, size_t len, const aerotex_job *j, int k)
{
    snprintf(buf, len, "%s.ckpt/state%04d.bin", j->out, k);
}

/* the bytes of a task record after its aerotex_task member */
#define BODY(task) ((char *)(task) + sizeof(aerotex_task))
#define BODY_SIZE(task_size) ((task_size) - sizeof(aerotex_task))

int aerotex_farm_resume(aerotex_job *j, int k, void *task, size_t task_size,
                        int width)
{
    char path[4200];
    ckpt_header want = header(j, k, task_size, width), got;
    const size_t frames = (size_t)j->loop.avail;
    /* (+1: a task without channels, the calibration circle, too) */
    float *row = malloc(sizeof(float) * ((size_t)width + 1));
    char *body = malloc(BODY_SIZE(task_size) + 1);
    FILE *f;
    int ok = 0;
    ckpt_path(path, sizeof path, j, k);
    f = row && body ? fopen(path, "rb") : NULL;
    if (f && fread(&got, sizeof got, 1, f) == 1 &&
        !memcmp(&got, &want, sizeof got) &&
        fread(body, BODY_SIZE(task_size), 1, f) == 1) {
        /* the channels straight into raw: a short file leaves them to be
           simulated again (they are all overwritten then) */
        size_t t = 0;
        for (; t < frames && fread(row, sizeof(float), (size_t)width, f) ==
                                 (size_t)width; t++)
            memcpy(j->raw + t * j->channels + (size_t)k * width, row,
                   sizeof(float) * (size_t)width);
        if (t == frames) {
            memcpy(BODY(task), body, BODY_SIZE(task_size));
            ok = 1;
        }
    }
    if (f)
        fclose(f);
    free(row);
    free(body);
    return ok;
}

void aerotex_farm_keep(aerotex_job *j, int k, const void *task,
                       size_t task_size, int width)
{
    char path[4200], tmp[4300];
    ckpt_header h = header(j, k, task_size, width);
    const size_t frames = (size_t)j->loop.avail;
    FILE *f;
    int bad;
    if (((const aerotex_task *)task)->err[0])
        return;
    ckpt_path(path, sizeof path, j, -1);
    if (aerotex_mkdir(path) && errno != EEXIST)
        return;
    ckpt_path(path, sizeof path, j, k);
    snprintf(tmp, sizeof tmp, "%s.%ld.tmp", path, (long)getpid());
    if (!(f = fopen(tmp, "wb")))
        return;
    bad = fwrite(&h, sizeof h, 1, f) != 1 ||
          fwrite((const char *)task + sizeof(aerotex_task),
                 BODY_SIZE(task_size), 1, f) != 1;
    for (size_t t = 0; t < frames && !bad; t++)
        bad = fwrite(j->raw + t * j->channels + (size_t)k * width,
                     sizeof(float), (size_t)width, f) != (size_t)width;
    bad |= fclose(f) != 0;
    if (bad || rename(tmp, path))
        remove(tmp);
    else {
        /* the finished task supersedes its solver state */
        state_path(path, sizeof path, j, k);
        remove(path);
    }
}

/* a solver state of task t to `path` in the checkpoint folder: written
   under a temporary name and renamed, so a killed writer leaves the old
   state or none, never half of one */
static void write_state(const aerotex_task *t, const char *path,
                        const void *state, size_t bytes)
{
    char dir[4200], tmp[4300];
    ckpt_header h = header(t->job, t->index, bytes, 0);
    FILE *f;
    int bad;
    ckpt_path(dir, sizeof dir, t->job, -1);
    if (aerotex_mkdir(dir) && errno != EEXIST)
        return;
    snprintf(tmp, sizeof tmp, "%s.%ld.tmp", path, (long)getpid());
    if (!(f = fopen(tmp, "wb")))
        return;
    bad = fwrite(&h, sizeof h, 1, f) != 1 ||
          fwrite(state, bytes, 1, f) != 1;
    bad |= fclose(f) != 0;
    if (bad || rename(tmp, path))
        remove(tmp);
}

void aerotex_farm_save_state(void *ctx, const void *state, size_t bytes)
{
    aerotex_task *t = ctx;
    char path[4200];
    state_path(path, sizeof path, t->job, t->index);
    write_state(t, path, state, bytes);
}

int aerotex_farm_load_state(void *ctx, void *state, size_t bytes)
{
    aerotex_task *t = ctx;
    char path[4200];
    ckpt_header want = header(t->job, t->index, bytes, 0), got;
    FILE *f;
    int ok;
    state_path(path, sizeof path, t->job, t->index);
    if (!(f = fopen(path, "rb")))
        return 0;
    ok = fread(&got, sizeof got, 1, f) == 1 &&
         !memcmp(&got, &want, sizeof got) && fread(state, bytes, 1, f) == 1;
    fclose(f);
    return ok;
}

/* object --slabs: each rank keeps its window's state in
   OUT.ckpt/stateNNNN.RRRofPPP.bin; a state is loaded only when every rank
   has one of the same step (body_flow's state begins with the step it
   continues from, an int64), so a job killed while some ranks were
   writing starts the direction again rather than mixing two steps */
static void slab_state_path(char *buf, size_t len, const aerotex_job *j,
                            int k)
{
    snprintf(buf, len, "%s.ckpt/state%04d.%03dof%03d.bin", j->out, k,
             aerotex_farm_rank(), aerotex_farm_size());
}

void aerotex_farm_save_slab_state(void *ctx, const void *state,
                                  size_t bytes)
{
    aerotex_task *t = ctx;
    char path[4200];
    slab_state_path(path, sizeof path, t->job, t->index);
    write_state(t, path, state, bytes);
}

int aerotex_farm_load_slab_state(void *ctx, void *state, size_t bytes)
{
    aerotex_task *t = ctx;
    char path[4200];
    ckpt_header want = header(t->job, t->index, bytes, 0), got;
    FILE *f;
    int ok = 0;
    long long step = -1, lo, hi;
    slab_state_path(path, sizeof path, t->job, t->index);
    if ((f = fopen(path, "rb"))) {
        ok = fread(&got, sizeof got, 1, f) == 1 &&
             !memcmp(&got, &want, sizeof got) &&
             bytes >= sizeof(int64_t) && fread(state, bytes, 1, f) == 1;
        fclose(f);
    }
    if (ok) {
        int64_t s64;
        memcpy(&s64, state, sizeof s64);
        step = (long long)s64;
    }
    MPI_Allreduce(&step, &lo, 1, MPI_LONG_LONG, MPI_MIN, MPI_COMM_WORLD);
    MPI_Allreduce(&step, &hi, 1, MPI_LONG_LONG, MPI_MAX, MPI_COMM_WORLD);
    return lo > 0 && lo == hi;
}

/* the slab states of direction k removed (its texture's task kept) */
void aerotex_farm_drop_slab_state(aerotex_job *j, int k)
{
    char path[4200];
    slab_state_path(path, sizeof path, j, k);
    remove(path);
    /* every rank's gone before rank 0 may remove the folder */
    MPI_Barrier(MPI_COMM_WORLD);
}

void aerotex_farm_done(aerotex_job *j)
{
    char path[4200];
    int n = j->channels;
    /* the task files of every width there may be: at most one per channel */
    for (int k = 0; k < n; k++) {
        ckpt_path(path, sizeof path, j, k);
        remove(path);
        state_path(path, sizeof path, j, k);
        remove(path);
    }
    ckpt_path(path, sizeof path, j, -1);
    rmdir(path);
}

/* --- gathering ------------------------------------------------------------ */

/* every rank here: a rank that finished its tasks waits asleep, polling
   each millisecond (a blocking collective would spin on a core that a
   rank still computing, or another job, could use) */
static void idle_barrier(void)
{
    const struct timespec ms = {0, 1000000};
    MPI_Request req;
    int done = 0;
    MPI_Ibarrier(MPI_COMM_WORLD, &req);
    for (;;) {
        MPI_Test(&req, &done, MPI_STATUS_IGNORE);
        if (done)
            break;
        nanosleep(&ms, NULL);
    }
}

int aerotex_farm_gather(aerotex_job *j, void *tasks, int n, size_t task_size,
                        int width)
{
    const int rank = aerotex_farm_rank(), size = aerotex_farm_size();
    const size_t frames = (size_t)j->loop.avail;
    const size_t rec = BODY_SIZE(task_size) + sizeof ((aerotex_task *)0)->err +
                       sizeof(float) * frames * (size_t)width;
    int *counts = NULL, *displs = NULL, bad = 0;
    char *buf = NULL;
    size_t mine = rank ? (size_t)aerotex_farm_count(n) : 0, total = 0;
    if (size == 1)
        return 0;
    idle_barrier();
    if (rank == 0) {
        counts = calloc((size_t)size, sizeof(int));
        displs = calloc((size_t)size, sizeof(int));
        for (int r = 1; r < size && counts && displs; r++) {
            size_t c = rec * (size_t)((n - r + size - 1) / size);
            bad |= total + c > INT_MAX;
            counts[r] = (int)c;
            displs[r] = (int)total;
            total += c;
        }
        bad |= !counts || !displs;
    } else {
        total = rec * mine;
        bad = total > INT_MAX;
    }
    if (!bad && total && !(buf = malloc(total)))
        bad = 1;
    /* every rank learns whether any cannot take part */
    MPI_Allreduce(MPI_IN_PLACE, &bad, 1, MPI_INT, MPI_LOR, MPI_COMM_WORLD);
    if (bad) {
        free(buf);
        free(counts);
        free(displs);
        return aerotex_job_fail(j, "the ranks' results are too large to "
                                   "gather (2 GB per rank) or out of memory");
    }
    if (rank) {
        char *p = buf;
        for (int k = rank; k < n; k += size) {
            aerotex_task *t = (aerotex_task *)((char *)tasks + k * task_size);
            memcpy(p, BODY(t), BODY_SIZE(task_size));
            p += BODY_SIZE(task_size);
            memcpy(p, t->err, sizeof t->err);
            p += sizeof t->err;
            for (size_t f = 0; f < frames; f++, p += sizeof(float) * width)
                memcpy(p, j->raw + f * j->channels + (size_t)k * width,
                       sizeof(float) * (size_t)width);
        }
    }
    /* rank 0's own tasks are in place already (counts[0] = 0) */
    MPI_Gatherv(rank ? buf : MPI_IN_PLACE, (int)(rank ? total : 0), MPI_BYTE,
                buf, counts, displs, MPI_BYTE, 0, MPI_COMM_WORLD);
    if (rank == 0)
        for (int r = 1; r < size; r++) {
            const char *p = buf + displs[r];
            for (int k = r; k < n; k += size) {
                aerotex_task *t = (aerotex_task *)((char *)tasks +
                                                   k * task_size);
                memcpy(BODY(t), p, BODY_SIZE(task_size));
                p += BODY_SIZE(task_size);
                memcpy(t->err, p, sizeof t->err);
                p += sizeof t->err;
                for (size_t f = 0; f < frames; f++, p += sizeof(float) * width)
                    memcpy(j->raw + f * j->channels + (size_t)k * width, p,
                           sizeof(float) * (size_t)width);
            }
        }
    free(buf);
    free(counts);
    free(displs);
    return 0;
}

void aerotex_farm_share(void *p, size_t n)
{
    if (aerotex_farm_size() > 1)
        idle_barrier();
    MPI_Bcast(p, (int)n, MPI_BYTE, 0, MPI_COMM_WORLD);
}

#else /* one process: one rank of one, no checkpoint */

void aerotex_farm_init(int *argc, char ***argv)
{
    (void)argc;
    (void)argv;
}

void aerotex_farm_finalize(void)
{
}

int aerotex_farm_rank(void)
{
    return 0;
}

int aerotex_farm_size(void)
{
    return 1;
}

int aerotex_farm_resume(aerotex_job *j, int k, void *task, size_t task_size,
                        int width)
{
    (void)j;
    (void)k;
    (void)task;
    (void)task_size;
    (void)width;
    return 0;
}

void aerotex_farm_keep(aerotex_job *j, int k, const void *task,
                       size_t task_size, int width)
{
    (void)j;
    (void)k;
    (void)task;
    (void)task_size;
    (void)width;
}

int aerotex_farm_gather(aerotex_job *j, void *tasks, int n, size_t task_size,
                        int width)
{
    (void)j;
    (void)tasks;
    (void)n;
    (void)task_size;
    (void)width;
    return 0;
}

void aerotex_farm_share(void *p, size_t n)
{
    (void)p;
    (void)n;
}

void aerotex_farm_save_state(void *ctx, const void *state, size_t bytes)
{
    (void)ctx;
    (void)state;
    (void)bytes;
}

int aerotex_farm_load_state(void *ctx, void *state, size_t bytes)
{
    (void)ctx;
    (void)state;
    (void)bytes;
    return 0;
}

void aerotex_farm_done(aerotex_job *j)
{
    (void)j;
}

#endif

int aerotex_farm_mine(int k)
{
    return k % aerotex_farm_size() == aerotex_farm_rank();
}

int aerotex_farm_count(int n)
{
    const int size = aerotex_farm_size(), rank = aerotex_farm_rank();
    return n > rank ? (n - rank + size - 1) / size : 0;
}
