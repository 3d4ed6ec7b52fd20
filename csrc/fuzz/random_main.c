/*
 * random_main.c - a main() for the fuzz targets that feeds them seeded
 * random inputs for a given time, built with $(CC) -O2 and no
 * instrumentation (make fuzz-random): some ten times libFuzzer's inputs a
 * second on targets whose calls are heavy under its sanitizers, which
 * reaches the numeric corners (subnormal products, a huge interval, a
 * 1e-290 s sample time) that a short coverage-guided run may not.
 *
 *   build/fuzz-random/fuzz_control SECONDS SEED [CRASH_FILE]
 *
 * Inputs of 8 to 1024 bytes; every other one "plausible" (the decoder's
 * selector bytes mostly below 160, fuzz.h), the rest raw bytes with one
 * in eight zero and one in eight an edge or extreme selector.  When a
 * target aborts (an oracle, fz_fail), the input is written to CRASH_FILE
 * (default crash-random-SEED) for make fuzz-replay or libFuzzer, and the
 * program dies of the signal.  Exit 0 after SECONDS without a failure.
 */
#define _POSIX_C_SOURCE 200809L
#include <fcntl.h>
#include <signal.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <unistd.h>

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

#define MAX_LEN 1024

static uint8_t input[MAX_LEN];
static size_t input_len;
static char crash_path[512];

/* the input being run, to crash_path: only async-signal-safe calls */
static void on_abort(int sig)
{
    const int fd = open(crash_path, O_WRONLY | O_CREAT | O_TRUNC, 0644);
    static const char head[] = "\nrandom: failing input written to ";
    if (fd >= 0) {
        if (write(fd, input, input_len) < 0) {
            /* nothing more to do in a handler */
        }
        close(fd);
    }
    if (write(2, head, sizeof head - 1) < 0 || write(2, crash_path, strlen(crash_path)) < 0
        || write(2, "\n", 1) < 0) {
        /* as above */
    }
    signal(sig, SIG_DFL);
    raise(sig);
}

/* xorshift64*: the same inputs for the same seed */
static uint64_t state;

static uint64_t next(void)
{
    state ^= state >> 12;
    state ^= state << 25;
    state ^= state >> 27;
    return state * 2685821657736338717ull;
}

static void make_input(void)
{
    const int plausible = (int)(next() & 1);
    size_t i;
    input_len = 8 + (size_t)(next() % (MAX_LEN - 7));
    for (i = 0; i < input_len; i++) {
        const uint64_t r = next();
        uint8_t b = (uint8_t)r;
        if (plausible) {
            if (b >= 160 && (r >> 40) % 8 != 0)
                b = (uint8_t)(b % 160);
        } else if ((r >> 8) % 8 == 0) {
            b = 0;
        } else if ((r >> 8) % 8 == 1) {
            b = (uint8_t)(160 + (r >> 16) % 96);
        }
        input[i] = b;
    }
}

int main(int argc, char **argv)
{
    double seconds;
    unsigned long long seed;
    long runs = 0;
    time_t end;

    if (argc < 3 || argc > 4) {
        fprintf(stderr, "usage: %s SECONDS SEED [CRASH_FILE]\n", argv[0]);
        return 2;
    }
    seconds = atof(argv[1]);
    seed = strtoull(argv[2], NULL, 10);
    if (argc == 4)
        snprintf(crash_path, sizeof crash_path, "%s", argv[3]);
    else
        snprintf(crash_path, sizeof crash_path, "crash-random-%llu", seed);
    state = 0x9E3779B97F4A7C15ull ^ (seed * 0xBF58476D1CE4E5B9ull);
    if (state == 0)
        state = 1;
    signal(SIGABRT, on_abort);
    end = time(NULL) + (time_t)(seconds > 0 ? seconds : 0);
    do {
        int k;
        for (k = 0; k < 64; k++, runs++) {
            make_input();
            LLVMFuzzerTestOneInput(input, input_len);
        }
    } while (time(NULL) < end);
    printf("random: %ld inputs, seed %llu, no failure\n", runs, seed);
    return 0;
}
