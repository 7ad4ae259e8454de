/* A host that must survive bad input: for each file, load it and, when it
 * loads, recognize, plan and list operations (serial work). Every call must
 * return; a status of TW_ERR_PANIC (a Thinwall bug) or a message that does
 * not name the file is a failure. Prints one line per file:
 *   FILE load=STATUS recognize=STATUS plan=STATUS operations=STATUS
 * and exits 0 when every file was survived that way, 1 otherwise. */
#include "thinwall.h"
#include <stdio.h>
#include <string.h>

static int failures = 0;

/* Record a call's status; a panic, or an error message without `file`, is a failure. */
static int seen(const char *file, const char *call, enum tw_status st) {
    if (st == TW_ERR_PANIC) {
        fprintf(stderr, "%s: %s panicked: %s\n", file, call, tw_last_error_message());
        failures++;
    } else if (st != TW_OK && strstr(tw_last_error_message(), file) == NULL) {
        fprintf(stderr, "%s: %s message does not name the file: %s\n", file, call, tw_last_error_message());
        failures++;
    }
    printf(" %s=%d", call, (int)st);
    return st == TW_OK;
}

int main(int argc, char **argv) {
    tw_options *opt = NULL;
    if (tw_options_new(&opt) != TW_OK || tw_options_set_parallel(opt, false) != TW_OK) {
        fprintf(stderr, "options: %s\n", tw_last_error_message());
        return 2;
    }
    for (int i = 1; i < argc; i++) {
        const char *file = argv[i];
        printf("%s", file);
        tw_part *part = NULL;
        if (seen(file, "load", tw_part_load_file(file, &part))) {
            tw_result *res = NULL;
            if (seen(file, "recognize", tw_recognize(part, opt, &res)))
                tw_result_free(res);
            tw_plan_result *plan = NULL;
            if (seen(file, "plan", tw_plan(part, opt, NULL, &plan)))
                tw_plan_free(plan);
            tw_operations_result *ops = NULL;
            if (seen(file, "operations", tw_operations(part, opt, NULL, 0.0, &ops)))
                tw_operations_free(ops);
            tw_part_free(part);
        }
        printf("\n");
    }
    tw_options_free(opt);
    return failures == 0 ? 0 : 1;
}
