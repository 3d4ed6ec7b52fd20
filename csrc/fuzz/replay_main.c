/*
 * replay_main.c - a main() for the fuzz targets without libFuzzer: runs
 * LLVMFuzzerTestOneInput once on every file named, and on every file of
 * every directory named (in name order), so that a compiler without
 * libFuzzer (gcc) can replay the corpus and the regression inputs under
 * its own sanitizers.
 *
 *   build/fuzz-replay/fuzz_hertz fuzz/corpus/fuzz_hertz fuzz/regressions/fuzz_hertz
 *
 * A missing directory counts as empty.  Each input gets FUZZ_REPLAY_TIMEOUT
 * seconds (default 10, libFuzzer's -timeout of fuzz-ci); when an input
 * aborts, hangs or a sanitizer stops the program, its name is printed
 * first, so that the failing file is known.
 */
#define _POSIX_C_SOURCE 200809L
#include <dirent.h>
#include <signal.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#if defined(__SANITIZE_ADDRESS__)
#define REPLAY_SANITIZER 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define REPLAY_SANITIZER 1
#endif
#endif
#ifdef REPLAY_SANITIZER
#include <sanitizer/common_interface_defs.h>
#endif

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

static char current[4096];   /* the input being run, for the failure message */

static void say_current(void)
{
    static const char head[] = "\nreplay: failing input: ";
    size_t n = strlen(current);
    if (write(2, head, sizeof head - 1) < 0 || write(2, current, n) < 0 || write(2, "\n", 1) < 0)
        return;
}

static void on_signal(int sig)
{
    if (sig == SIGALRM) {
        static const char msg[] = "\nreplay: timeout";
        if (write(2, msg, sizeof msg - 1) < 0)
            _exit(3);
    }
    say_current();
    signal(sig, SIG_DFL);
    raise(sig);
}

static int run_file(const char *path, unsigned timeout)
{
    FILE *f = fopen(path, "rb");
    unsigned char *buf;
    long len;

    if (!f) {
        fprintf(stderr, "replay: cannot open %s\n", path);
        return 1;
    }
    if (fseek(f, 0, SEEK_END) != 0 || (len = ftell(f)) < 0 || fseek(f, 0, SEEK_SET) != 0) {
        fclose(f);
        fprintf(stderr, "replay: cannot read %s\n", path);
        return 1;
    }
    buf = malloc(len > 0 ? (size_t)len : 1);
    if (!buf || fread(buf, 1, (size_t)len, f) != (size_t)len) {
        free(buf);
        fclose(f);
        fprintf(stderr, "replay: cannot read %s\n", path);
        return 1;
    }
    fclose(f);
    strncpy(current, path, sizeof current - 1);
    alarm(timeout);
    LLVMFuzzerTestOneInput(buf, (size_t)len);
    alarm(0);
    free(buf);
    return 0;
}

static int cmp_names(const void *a, const void *b)
{
    return strcmp(*(char *const *)a, *(char *const *)b);
}

/* Every regular file of dir, in name order; *count incremented. */
static int run_dir(const char *dir, unsigned timeout, long *count)
{
    DIR *d = opendir(dir);
    struct dirent *e;
    char **names = NULL;
    size_t n = 0, cap = 0, i;
    int bad = 0;

    if (!d)
        return 0;
    while ((e = readdir(d)) != NULL) {
        if (e->d_name[0] == '.')
            continue;
        if (n == cap) {
            char **more = realloc(names, (cap = cap ? 2 * cap : 64) * sizeof *names);
            if (!more)
                abort();
            names = more;
        }
        names[n] = malloc(strlen(dir) + strlen(e->d_name) + 2);
        if (!names[n])
            abort();
        sprintf(names[n], "%s/%s", dir, e->d_name);
        n++;
    }
    closedir(d);
    if (n > 0)
        qsort(names, n, sizeof *names, cmp_names);
    for (i = 0; i < n; i++) {
        struct stat sb;
        if (stat(names[i], &sb) == 0 && S_ISREG(sb.st_mode)) {
            bad |= run_file(names[i], timeout);
            (*count)++;
        }
        free(names[i]);
    }
    free(names);
    return bad;
}

int main(int argc, char **argv)
{
    const char *t = getenv("FUZZ_REPLAY_TIMEOUT");
    const unsigned timeout = t && atoi(t) > 0 ? (unsigned)atoi(t) : 10u;
    long count = 0;
    int i, bad = 0;

    signal(SIGABRT, on_signal);
    signal(SIGALRM, on_signal);
#ifdef REPLAY_SANITIZER
    __sanitizer_set_death_callback(say_current);
#endif
    for (i = 1; i < argc; i++) {
        struct stat sb;
        if (stat(argv[i], &sb) == 0 && S_ISDIR(sb.st_mode)) {
            bad |= run_dir(argv[i], timeout, &count);
        } else if (stat(argv[i], &sb) == 0) {
            bad |= run_file(argv[i], timeout);
            count++;
        }
    }
    printf("%s: %ld input(s) replayed\n", argv[0], count);
    return bad;
}
