/*
 * robust_check.h - turning a robustness case into Check tests: each case
 * runs our renderer in double and in float and must count no failure and no
 * NaN (a precision the case does not apply to passes, with its reason in
 * docs/robustness.md).
 */
#ifndef RAYTRACE_TESTS_ROBUST_CHECK_H
#define RAYTRACE_TESTS_ROBUST_CHECK_H

#include <check.h>

#include "robust/robust.h"

static inline void rb_check_case(const char *id, rt_precision precision)
{
    const rb_case *c = rb_case_find(id);
    ck_assert_msg(c != NULL, "no robustness case %s", id);
    rb_result r;
    rb_case_run(c, RB_OURS, precision, &r);
    if (!r.applicable)
        return;
    ck_assert_msg(r.failures == 0 && r.nans == 0,
                  "%s in %s: %ld of %ld failed (%s), %ld NaN; %s; setup: %s",
                  id, precision == RT_PRECISION_FLOAT ? "float" : "double",
                  r.failures, r.total, c->criterion, r.nans, r.note, c->setup);
}

/* A test case with room for slow machines and sanitizers. */
static inline TCase *rb_tcase(const char *name)
{
    TCase *tc = tcase_create(name);
    tcase_set_timeout(tc, 240);
    return tc;
}

#endif /* RAYTRACE_TESTS_ROBUST_CHECK_H */
