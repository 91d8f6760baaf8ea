/* Negative control for check-valgrind (tests/robust/valgrind.sh): a
 * program with the two bugs memcheck must catch. With the argument
 * "overflow" it reads one float past a heap block (memcheck: Invalid
 * read), with "leak" it loses a block (memcheck: definitely lost). Built
 * -O0 so that neither bug is optimised away. Never shipped. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

int main(int argc, char **argv)
{
    float *block = malloc(4 * sizeof(float));
    volatile float sink;
    if (block == NULL || argc < 2)
        return 2;
    memset(block, 0, 4 * sizeof(float));
    if (strcmp(argv[1], "leak") == 0) {
        sink = block[0];
        block = NULL; /* lost */
    } else {
        sink = block[4]; /* one past the end */
        free(block);
    }
    (void)sink;
    printf("valgrind-control %s done\n", argv[1]);
    return 0;
}
