/* bench/mpi.sh: the exchange a slab-decomposed 3D flow's pressure solve
 * needs (docs/cluster.md), measured: FFTW's MPI transpose of a spectrum
 * of NZ x NY x (NX/2+1) complex floats distributed in z slabs, to lines
 * along z and back, REPS times. Prints the bytes a rank sends a step (two
 * transposes) and the rate. Not a test. Built by bench/mpi.sh with mpicc
 * -lfftw3f_mpi -lfftw3f. Usage: mpirun -np N mpi-transpose NX NY NZ REPS */
#include <fftw3-mpi.h>
#include <mpi.h>
#include <stdio.h>
#include <stdlib.h>

int main(int argc, char **argv)
{
    int rank, size;
    MPI_Init(&argc, &argv);
    fftwf_mpi_init();
    MPI_Comm_rank(MPI_COMM_WORLD, &rank);
    MPI_Comm_size(MPI_COMM_WORLD, &size);
    const ptrdiff_t nx = argc > 1 ? atoi(argv[1]) : 96;
    const ptrdiff_t ny = argc > 2 ? atoi(argv[2]) : 96;
    const ptrdiff_t nz = argc > 3 ? atoi(argv[3]) : 192;
    const int reps = argc > 4 ? atoi(argv[4]) : 20;
    /* a complex value is 2 floats: the transpose of an nz x ny matrix of
       (nx/2+1)-complex blocks */
    const ptrdiff_t block = 2 * (nx / 2 + 1);
    ptrdiff_t local_n0, start0, local_n1, start1;
    ptrdiff_t alloc = fftwf_mpi_local_size_many_transposed(
        2, (ptrdiff_t[]){nz, ny}, block, FFTW_MPI_DEFAULT_BLOCK,
        FFTW_MPI_DEFAULT_BLOCK, MPI_COMM_WORLD, &local_n0, &start0,
        &local_n1, &start1);
    float *a = fftwf_alloc_real((size_t)alloc);
    fftwf_plan there = fftwf_mpi_plan_many_transpose(
        nz, ny, block, FFTW_MPI_DEFAULT_BLOCK, FFTW_MPI_DEFAULT_BLOCK, a, a,
        MPI_COMM_WORLD, FFTW_ESTIMATE);
    fftwf_plan back = fftwf_mpi_plan_many_transpose(
        ny, nz, block, FFTW_MPI_DEFAULT_BLOCK, FFTW_MPI_DEFAULT_BLOCK, a, a,
        MPI_COMM_WORLD, FFTW_ESTIMATE);
    for (ptrdiff_t i = 0; i < alloc; i++)
        a[i] = (float)(i % 97);
    MPI_Barrier(MPI_COMM_WORLD);
    double t0 = MPI_Wtime();
    for (int r = 0; r < reps; r++) {
        fftwf_execute(there);
        fftwf_execute(back);
    }
    double t = (MPI_Wtime() - t0) / reps, tmax;
    MPI_Reduce(&t, &tmax, 1, MPI_DOUBLE, MPI_MAX, 0, MPI_COMM_WORLD);
    /* what a rank sends a step: its share, but the part it keeps, twice */
    double bytes = 2.0 * 4.0 * block * ny * nz / size * (size - 1) / size;
    if (rank == 0)
        printf("  FFTW MPI transposes, %td x %td x %td spectrum, %d ranks: "
               "%.2f MB a rank a step in %.2f ms: %.2f GB/s a rank\n",
               nx, ny, nz, size, bytes / 1e6, 1e3 * tmax,
               bytes / tmax / 1e9);
    fftwf_destroy_plan(there);
    fftwf_destroy_plan(back);
    fftwf_free(a);
    fftwf_mpi_cleanup();
    MPI_Finalize();
    return 0;
}
