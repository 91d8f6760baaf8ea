/* Negative control for check-asan: an external with the two bugs the
 * sanitized Pd run must catch. On load it reads one float past a heap
 * block (ASan: heap-buffer-overflow) unless the creation argument is 1,
 * then it loses a block (LSan: leak at Pd's exit). Never shipped. */
#include "m_pd.h"
#include <stdlib.h>

static t_class *asan_control_class;
static volatile float sink;

typedef struct {
    t_object x_obj;
} t_asan_control;

static void *asan_control_new(t_floatarg leak_only)
{
    t_asan_control *x = (t_asan_control *)pd_new(asan_control_class);
    float *block = malloc(4 * sizeof(float));
    if (leak_only == 1) {
        block[0] = 1;
        sink = block[0];
        block = NULL; /* lost */
    } else {
        sink = block[4]; /* one past the end */
        free(block);
    }
    return x;
}

void asan_control_setup(void)
{
    asan_control_class = class_new(gensym("asan_control"),
                                   (t_newmethod)(t_method)asan_control_new, 0,
                                   sizeof(t_asan_control), 0, A_DEFFLOAT, 0);
}
