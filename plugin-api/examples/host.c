/*
 * A small CAD-host-like program over the Thinwall C ABI: load a STEP part
 * from memory, recognize its stiffness features in a set-up, print them and
 * their connections, and exercise the error paths.
 *
 *   cc -Wall -Werror -std=c11 -Iplugin-api/include host.c -Ltarget/release -lthinwall -o host
 *   ./host PART.step [VOLUME.step ...]   (volumes removed in the order given)
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "thinwall.h"

static unsigned char *read_all(const char *path, size_t *len) {
    FILE *f = fopen(path, "rb");
    if (!f) return NULL;
    fseek(f, 0, SEEK_END);
    long n = ftell(f);
    fseek(f, 0, SEEK_SET);
    unsigned char *buf = n > 0 ? malloc((size_t)n) : NULL;
    if (buf && fread(buf, 1, (size_t)n, f) != (size_t)n) {
        free(buf);
        buf = NULL;
    }
    fclose(f);
    *len = buf ? (size_t)n : 0;
    return buf;
}

static int check(int ok, const char *what) {
    if (!ok) fprintf(stderr, "host: FAILED: %s\n", what);
    return ok ? 0 : 1;
}

int main(int argc, char **argv) {
    int failures = 0;
    if (argc < 2) {
        fprintf(stderr, "usage: %s PART.step [VOLUME.step ...]\n", argv[0]);
        return 2;
    }
    printf("thinwall %s (header %s), ABI %u\n", tw_version(), THINWALL_VERSION, tw_abi_version());
    failures += check(tw_abi_version() == TW_ABI_VERSION, "the library's ABI is the header's");

    /* Error paths: a missing file, NULL arguments, bad settings. */
    tw_part *missing = (tw_part *)1;
    tw_status st = tw_part_load_file("/no/such/part.step", &missing);
    failures += check(st == TW_ERR_IO && missing == NULL, "missing file gives TW_ERR_IO and a NULL part");
    failures += check(strstr(tw_last_error_message(), "/no/such/part.step") != NULL, "error message names the file");
    failures += check(tw_part_load_file(NULL, &missing) == TW_ERR_NULL_ARGUMENT, "NULL path rejected");
    failures += check(tw_part_load_memory((const uint8_t *)"garbage", 7, &missing) == TW_ERR_PARSE, "garbage is a parse error");
    failures += check(tw_recognize(NULL, NULL, NULL) == TW_ERR_NULL_ARGUMENT, "NULL part rejected");
    failures += check(tw_result_feature_count(NULL) == 0 && tw_result_feature_kind(NULL, 0) == NULL, "NULL result accessors are safe");
    tw_part_free(NULL);
    tw_result_free(NULL);
    tw_options_free(NULL);
    tw_string_free(NULL);

    /* The part, from memory. */
    size_t len = 0;
    unsigned char *data = read_all(argv[1], &len);
    if (!data) {
        fprintf(stderr, "host: cannot read %s\n", argv[1]);
        return 2;
    }
    tw_part *part = NULL;
    st = tw_part_load_memory(data, len, &part);
    free(data);
    if (st != TW_OK) {
        fprintf(stderr, "host: load failed (%d): %s\n", (int)st, tw_last_error_message());
        return 1;
    }
    printf("faces: %zu\n", tw_part_face_count(part));

    tw_options *opt = NULL;
    failures += check(tw_options_new(&opt) == TW_OK, "options created");
    failures += check(tw_options_set_up(opt, 0.0, 0.0, 0.0) == TW_ERR_INVALID_ARGUMENT, "zero up rejected");
    failures += check(tw_options_set_force(opt, -1.0) == TW_ERR_INVALID_ARGUMENT, "negative force rejected");
    failures += check(tw_options_set_up(opt, 0.0, 0.0, 1.0) == TW_OK, "up set");
    failures += check(tw_options_set_tool_diameter(opt, 12.0) == TW_OK, "tool diameter set");

    tw_result *res = NULL;
    st = tw_recognize(part, opt, &res);
    if (st != TW_OK) {
        fprintf(stderr, "host: recognize failed (%d): %s\n", (int)st, tw_last_error_message());
        return 1;
    }
    size_t n = tw_result_feature_count(res);
    printf("features: %zu\n", n);
    for (size_t i = 0; i < n; i++) {
        size_t nfaces = 0;
        tw_result_feature_faces(res, i, NULL, 0, &nfaces);
        uint64_t *ids = malloc(sizeof(uint64_t) * (nfaces ? nfaces : 1));
        size_t got = 0;
        if (nfaces > 1) {
            failures += check(tw_result_feature_faces(res, i, ids, 1, &got) == TW_ERR_BUFFER_TOO_SMALL && got == nfaces,
                              "small buffer reported with the needed length");
        }
        failures += check(tw_result_feature_faces(res, i, ids, nfaces, &got) == TW_OK && got == nfaces, "face ids copied");
        double t = 0, h = 0, l = 0;
        bool thin = false;
        if (tw_result_feature_wall(res, i, &t, &h, &l, &thin) == TW_OK) {
            printf("  %-4s %-7s t=%.2f h=%.2f L=%.2f %s faces=%zu first=#%llu\n", tw_result_feature_id(res, i),
                   tw_result_feature_kind(res, i), t, h, l, thin ? "thin" : "thick", got, (unsigned long long)ids[0]);
            double below = 0;
            bool below_thin = false;
            if (tw_result_feature_other_side(res, i, &below, &below_thin) == TW_OK) {
                printf("       through its base: other side h=%.2f %s\n", below, below_thin ? "thin" : "thick");
            }
        } else {
            printf("  %-4s %-7s faces=%zu first=#%llu\n", tw_result_feature_id(res, i), tw_result_feature_kind(res, i),
                   got, (unsigned long long)ids[0]);
        }
        free(ids);
    }
    failures += check(tw_result_feature_kind(res, n) == NULL, "kind past the end is NULL");
    /* Machining features: sizes, a pocket's radii, a hole's stages. */
    size_t nm = tw_result_machining_count(res);
    printf("machining features: %zu\n", nm);
    for (size_t i = 0; i < nm; i++) {
        double depth = 0, length = 0, width = 0, tool = 0, corner = 0, fillet = 0, draft = 0;
        failures += check(tw_result_machining_sizes(res, i, &depth, &length, &width, &tool) == TW_OK, "machining sizes read");
        failures += check(tw_result_machining_blends(res, i, &corner, &fillet, &draft) == TW_OK, "machining radii read");
        printf("  %-4s %-8s depth=%.2f %.2f x %.2f tool=%.2f R=%.2f r=%.2f\n", tw_result_machining_id(res, i),
               tw_result_machining_kind(res, i), depth, length, width, tool, corner, fillet);
        tw_hole_end entry, exit;
        tw_hole_tip tip;
        double ea = 0, es = 0, xa = 0, xs = 0, ta = 0;
        size_t nb = 0;
        tw_status hs = tw_result_machining_hole(res, i, &entry, &ea, &es, &exit, &xa, &xs, &nb, &tip, &ta);
        if (strcmp(tw_result_machining_kind(res, i), "hole") == 0) {
            failures += check(hs == TW_OK && nb >= 1, "a hole's stages read");
            for (size_t k = 0; k < nb; k++) {
                double bd = 0, bh = 0;
                failures += check(tw_result_machining_bore(res, i, k, &bd, &bh) == TW_OK && bd > 0 && bh > 0, "bore read");
                printf("    bore %zu: %.2f x %.2f\n", k + 1, bd, bh);
            }
            failures += check(tw_result_machining_bore(res, i, nb, NULL, NULL) == TW_ERR_OUT_OF_RANGE, "bore past the last refused");
        } else {
            failures += check(hs == TW_ERR_NOT_APPLICABLE, "stages of a non-hole refused");
        }
    }
    failures += check(tw_result_machining_kind(res, nm) == NULL, "machining kind past the end is NULL");
    failures += check(tw_result_machining_sizes(res, nm, NULL, NULL, NULL, NULL) == TW_ERR_OUT_OF_RANGE,
                      "machining sizes past the end refused");
    size_t nc = tw_result_connection_count(res);
    printf("connections: %zu\n", nc);
    for (size_t i = 0; i < nc; i++) {
        tw_connection_kind k;
        const char *a = NULL, *b = NULL;
        if (tw_result_connection(res, i, &k, &a, &b) == TW_OK)
            printf("  %s %s %s\n", a, k == TW_CONNECTION_CROSSING ? "x" : "->", b);
    }
    char *json = NULL;
    failures += check(tw_result_to_json(res, &json) == TW_OK && json != NULL, "json produced");
    if (json) {
        failures += check(strstr(json, "\"schema\": \"thinwall/recognition/1\"") != NULL, "json carries its schema");
        printf("json: %zu bytes\n", strlen(json));
        tw_string_free(json);
    }
    tw_result_free(res);

    /* The plan: sequence constraints from the shipped rules. */
    tw_plan_result *plan = NULL;
    st = tw_plan(part, NULL, NULL, &plan);
    failures += check(st == TW_OK && plan != NULL, "plan made");
    if (plan) {
        size_t ns = tw_plan_sequence_count(plan);
        printf("sequence: %zu\n", ns);
        for (size_t i = 0; i < ns; i++) {
            const char *a = NULL, *b = NULL;
            tw_relation r;
            failures += check(tw_plan_sequence_pair(plan, i, &a, &b, &r) == TW_OK, "constraint read");
            printf("  %s %s %s (%s)\n", a, r == TW_RELATION_BEFORE ? "before" : "with", b,
                   tw_plan_sequence_rule(plan, i));
        }
        failures += check(tw_plan_sequence_pair(plan, ns, NULL, NULL, NULL) == TW_ERR_OUT_OF_RANGE,
                          "constraint past the end is out of range");
        /* The removal plan: every machining feature, its place in the
           order, its volume, and its solids as STEP text. */
        size_t nf = tw_plan_feature_count(plan);
        double total = 0.0;
        size_t steps = 0;
        printf("machining features: %zu\n", nf);
        for (size_t i = 0; i < nf; i++) {
            const char *id = NULL, *owner = NULL;
            tw_feature_class cls;
            size_t at = 0;
            double vol = 0.0;
            failures += check(tw_plan_feature(plan, i, &id, &owner, &cls, &at, &vol) == TW_OK,
                              "feature read");
            failures += check(at < nf, "feature has a place in the order");
            total += vol;
            char *step = NULL;
            size_t skipped = 0;
            failures += check(tw_plan_feature_step(plan, i, &step, &skipped) == TW_OK && step != NULL,
                              "feature STEP written");
            if (step && strstr(step, "MANIFOLD_SOLID_BREP")) {
                steps++;
            }
            tw_string_free(step);
            const char *type = tw_plan_feature_type(plan, i);
            failures += check(type != NULL && tw_plan_feature_adjacency(plan, i) != NULL, "feature typed");
            if (i < 3) {
                printf("  %s owner %s class %d order %zu volume %.1f mm3 type %s adjacency %s\n", id,
                       owner ? owner : "-", (int)cls, at, vol, type, tw_plan_feature_adjacency(plan, i));
            }
        }
        printf("removed: %.1f mm3 in %zu features, %zu with solids as STEP\n", total, nf, steps);
        failures += check(nf > 0 && steps > 0, "the plan has machining features with solids");
        failures += check(tw_plan_feature(plan, nf, NULL, NULL, NULL, NULL, NULL) == TW_ERR_OUT_OF_RANGE,
                          "feature past the end is out of range");
        tw_plan_free(plan);
    }
    /* Flank milling of the planar faces: which are advisable. */
    tw_access_result *acc = NULL;
    st = tw_access(part, NULL, 0.0, 0.0, &acc);
    failures += check(st == TW_OK && acc != NULL, "access computed");
    if (acc) {
        size_t na = tw_access_face_count(acc), advisable = 0;
        for (size_t i = 0; i < na; i++) {
            uint64_t id = 0;
            tw_face_nature nature;
            double area = 0.0, reached = 0.0;
            bool ok = false;
            failures += check(tw_access_face(acc, i, &id, &nature, &area, &reached, &ok) == TW_OK,
                              "access face read");
            failures += check(reached >= 0.0 && reached <= 1.0 + 1e-9 && area > 0.0, "access figures");
            advisable += ok ? 1 : 0;
        }
        printf("flank milling: %zu of %zu planar faces advisable\n", advisable, na);
        failures += check(tw_access_face(acc, na, NULL, NULL, NULL, NULL, NULL) == TW_ERR_OUT_OF_RANGE,
                          "access face past the end is out of range");
        /* Reach with material in the way: every face, the Ø12 tool. */
        size_t nr = tw_access_reach_count(acc), whole = 0;
        for (size_t i = 0; i < nr; i++) {
            uint64_t id = 0;
            double fraction = -1.0, lost = -1.0, largest = 0.0;
            failures += check(tw_access_reach(acc, i, &id, &fraction, &lost, &largest) == TW_OK,
                              "reach face read");
            failures += check(fraction >= 0.0 && fraction <= 1.0 && lost >= 0.0 && id > 0, "reach figures");
            whole += fraction >= 1.0 - 1e-4 ? 1 : 0;
        }
        printf("reach: %zu of %zu faces reached whole by the Ø12 tool\n", whole, nr);
        failures += check(nr > 0 && tw_access_reach(acc, nr, NULL, NULL, NULL, NULL) == TW_ERR_OUT_OF_RANGE,
                          "reach face past the end is out of range");
        tw_access_free(acc);
    }
    tw_access_result *bad_access = NULL;
    failures += check(tw_access(part, NULL, -1.0, 0.0, &bad_access) == TW_ERR_INVALID_ARGUMENT &&
                          bad_access == NULL,
                      "a negative tool diameter is an invalid argument");

    tw_plan_result *bad = NULL;
    failures += check(tw_plan(part, NULL, "[[rule]]\nname = 1\n", &bad) == TW_ERR_INVALID_CONFIG && bad == NULL,
                      "a bad rule text is an invalid config");

    /* Operations of the set-up with a shop's two end mills (NULL would
       take the shipped library). */
    static const char *two_mills =
        "[[tool]]\nname = \"EM20\"\nkind = \"flat_end_mill\"\ndiameter = 20.0\ncorner_radius = 1.0\n"
        "cutting_length = 45.0\nstick_out = 75.0\nteeth = 3\ncutting_speed_m_min = 700.0\n"
        "feed_per_tooth_mm = 0.12\naxial_depth_mm = 10.0\nradial_depth_mm = 12.0\n"
        "[[tool]]\nname = \"EM8\"\nkind = \"flat_end_mill\"\ndiameter = 8.0\n"
        "cutting_length = 24.0\nstick_out = 40.0\nteeth = 3\ncutting_speed_m_min = 600.0\n"
        "feed_per_tooth_mm = 0.05\naxial_depth_mm = 4.0\nradial_depth_mm = 4.0\n";
    tw_operations_result *ops = NULL;
    st = tw_operations(part, NULL, two_mills, 0.0, &ops);
    if (st == TW_ERR_UNSUPPORTED) {
        printf("operations: not yet for this part: %s\n", tw_last_error_message());
    } else {
        failures += check(st == TW_OK && ops != NULL, "operations planned");
    }
    if (ops) {
        size_t no = tw_operations_count(ops), drills = 0;
        double minutes = 0.0, volume = 0.0;
        for (size_t i = 0; i < no; i++) {
            tw_stage stage;
            double d = 0.0, top = 0.0, bottom = 0.0, area = -1.0, vol = -1.0, t = -1.0;
            failures += check(tw_operation(ops, i, &stage, &d, &top, &bottom, &area, &vol, &t) == TW_OK,
                              "operation read");
            failures += check(d > 0.0 && top >= bottom && area >= 0.0 && vol >= 0.0 && t >= 0.0,
                              "operation figures");
            failures += check(tw_operation_tool(ops, i) != NULL, "operation tool named");
            drills += stage == TW_STAGE_DRILL ? 1 : 0;
            minutes += t;
            volume += vol;
        }
        size_t changes = 0, plain = 0;
        failures += check(tw_operations_tool_changes(ops, &changes, &plain) == TW_OK && changes <= plain,
                          "no more tool changes than the plain order");
        printf("operations: %zu (%zu drilling), %zu tool changes (%zu plain), %.1f mm3, %.2f min\n", no,
               drills, changes, plain, volume, minutes);
        failures += check(tw_operation(ops, no, NULL, NULL, NULL, NULL, NULL, NULL, NULL) == TW_ERR_OUT_OF_RANGE &&
                              tw_operation_tool(ops, no) == NULL,
                          "operation past the end is out of range");
        tw_operations_free(ops);
    }
    tw_operations_result *bad_ops = NULL;
    failures += check(tw_operations(part, NULL, "[[tool]]\nname = \"X\"\n", 0.0, &bad_ops) == TW_ERR_INVALID_CONFIG &&
                          bad_ops == NULL,
                      "a bad tool library is an invalid config");

    /* Optional: classify volumes given after the part (removed in order). */
    if (argc > 2) {
        size_t nv = (size_t)(argc - 2);
        tw_part **vols = calloc(nv, sizeof(tw_part *));
        size_t *before = calloc(nv > 1 ? 2 * (nv - 1) : 1, sizeof(size_t));
        for (size_t i = 0; i < nv; i++) {
            if (tw_part_load_file(argv[2 + i], &vols[i]) != TW_OK) {
                fprintf(stderr, "host: %s\n", tw_last_error_message());
                failures++;
            }
            if (i + 1 < nv) {
                before[2 * i] = i;
                before[2 * i + 1] = i + 1;
            }
        }
        tw_classification *cls = NULL;
        st = tw_classify(part, (const tw_part *const *)vols, nv, before, nv > 1 ? nv - 1 : 0, opt, &cls);
        failures += check(st == TW_OK, "classification");
        for (size_t i = 0; i < tw_classification_count(cls); i++)
            printf("volume %zu: %s (%s)\n", i, tw_classification_type(cls, i), tw_classification_product_adjacency(cls, i));
        size_t bad[2] = {0, 99};
        tw_classification *none = (tw_classification *)1;
        failures += check(tw_classify(part, (const tw_part *const *)vols, nv, bad, 1, opt, &none) == TW_ERR_INVALID_SEQUENCE && none == NULL,
                          "a sequence naming a missing volume is rejected");
        tw_classification_free(cls);
        for (size_t i = 0; i < nv; i++) tw_part_free(vols[i]);
        free(vols);
        free(before);
    }
    tw_options_free(opt);
    tw_part_free(part);
    printf("%s\n", failures ? "host: FAILED" : "host: ok");
    return failures ? 1 : 0;
}
