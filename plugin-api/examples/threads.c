/*
 * Several threads recognizing one part at once through the C ABI: the
 * "safe to share between threads" promise of tw_part and tw_options.
 * Every thread's JSON must equal the one made before the threads start,
 * and each thread's error message stays its own.
 *
 *   cc -Wall -Werror -std=c11 -pthread -Iplugin-api/include threads.c -Ltarget/release -lthinwall -o threads
 *   ./threads PART.step [THREADS]
 */
#include <pthread.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "thinwall.h"

struct job {
    const tw_part *part;
    const tw_options *opt;
    const char *expected;
    int ok;
};

static void *work(void *arg) {
    struct job *j = arg;
    tw_result *res = NULL;
    char *json = NULL;
    j->ok = tw_recognize(j->part, j->opt, &res) == TW_OK && tw_result_to_json(res, &json) == TW_OK &&
            strcmp(json, j->expected) == 0;
    /* A failure on this thread sets this thread's message only. */
    tw_part *none = NULL;
    j->ok = j->ok && tw_part_load_memory((const uint8_t *)"x", 1, &none) == TW_ERR_PARSE &&
            strlen(tw_last_error_message()) > 0;
    tw_string_free(json);
    tw_result_free(res);
    return NULL;
}

int main(int argc, char **argv) {
    if (argc < 2) {
        fprintf(stderr, "usage: %s PART.step [THREADS]\n", argv[0]);
        return 2;
    }
    int n = argc > 2 ? atoi(argv[2]) : 4;
    if (n < 1 || n > 64) n = 4;
    /* "parallel" as a third argument: each call also uses worker threads. */
    int parallel = argc > 3 && strcmp(argv[3], "parallel") == 0;
    if (tw_abi_version() != TW_ABI_VERSION) {
        fprintf(stderr, "threads: library ABI %u, header %u\n", tw_abi_version(), (unsigned)TW_ABI_VERSION);
        return 1;
    }
    tw_part *part = NULL;
    tw_options *opt = NULL;
    if (tw_part_load_file(argv[1], &part) != TW_OK || tw_options_new(&opt) != TW_OK ||
        tw_options_set_parallel(opt, parallel) != TW_OK) {
        fprintf(stderr, "threads: %s\n", tw_last_error_message());
        return 1;
    }
    tw_result *res = NULL;
    char *expected = NULL;
    if (tw_recognize(part, opt, &res) != TW_OK || tw_result_to_json(res, &expected) != TW_OK) {
        fprintf(stderr, "threads: %s\n", tw_last_error_message());
        return 1;
    }
    tw_result_free(res);
    pthread_t *ids = calloc((size_t)n, sizeof(pthread_t));
    struct job *jobs = calloc((size_t)n, sizeof(struct job));
    for (int i = 0; i < n; i++) {
        jobs[i] = (struct job){part, opt, expected, 0};
        pthread_create(&ids[i], NULL, work, &jobs[i]);
    }
    int failures = 0;
    for (int i = 0; i < n; i++) {
        pthread_join(ids[i], NULL);
        if (!jobs[i].ok) {
            fprintf(stderr, "threads: thread %d disagreed\n", i);
            failures++;
        }
    }
    /* The main thread's message is untouched by the threads' failures. */
    if (strlen(tw_last_error_message()) != 0) {
        fprintf(stderr, "threads: a thread's error leaked into the main thread\n");
        failures++;
    }
    free(ids);
    free(jobs);
    tw_string_free(expected);
    tw_options_free(opt);
    tw_part_free(part);
    printf("%s (%d threads)\n", failures ? "threads: FAILED" : "threads: ok", n);
    return failures ? 1 : 0;
}
