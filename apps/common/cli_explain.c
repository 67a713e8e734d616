/*
 * cli_explain.c - a ray tree's rays and terms as the rendering model names
 * them (see cli_explain.h).
 */
#include "cli_explain.h"

/* The first child of node i of `kind`, or -1. */
static long child_of(const rt_ray_node *nodes, size_t count, size_t i,
                     rt_ray_kind kind)
{
    for (size_t c = i + 1; c < count; c++)
        if (nodes[c].parent == (int)i && nodes[c].kind == kind)
            return (long)c;
    return -1;
}

int cli_explain_total_reflection(const rt_ray_node *nodes, size_t count,
                                 size_t i)
{
    if (i >= count || nodes[i].kind != RT_RAY_REFLECTED ||
        nodes[i].parent < 0)
        return 0;
    size_t parent = (size_t)nodes[i].parent;
    return nodes[parent].hit && nodes[parent].transmission > 0 &&
           child_of(nodes, count, parent, RT_RAY_REFRACTED) < 0;
}

const char *cli_explain_ray_name(const rt_ray_node *nodes, size_t count,
                                 size_t i)
{
    static const char *const names[] = {"camera", "shadow", "reflected",
                                        "refracted"};
    if (cli_explain_total_reflection(nodes, count, i))
        return "totally reflected";
    return names[nodes[i].kind];
}

static void add(rt_color *sum, rt_color c, double share)
{
    sum->r += share * c.r;
    sum->g += share * c.g;
    sum->b += share * c.b;
}

int cli_explain_terms(const rt_ray_node *nodes, size_t count, size_t i,
                      rt_color *direct, rt_color *reflection,
                      rt_color *refraction)
{
    const rt_color zero = {0, 0, 0};
    *direct = *reflection = *refraction = zero;
    int total = 0;
    for (size_t c = i + 1; c < count; c++) {
        if (nodes[c].parent != (int)i)
            continue;
        if (nodes[c].kind == RT_RAY_SHADOW) {
            add(direct, nodes[c].subtotal, 1);
        } else if (nodes[c].kind == RT_RAY_REFRACTED) {
            add(refraction, nodes[c].subtotal, 1);
        } else if (cli_explain_total_reflection(nodes, count, c)) {
            /* one ray of weight k + t for k C_R + t C_T, C_T = C_R */
            double k = nodes[i].k, t = nodes[i].transmission;
            add(reflection, nodes[c].subtotal, k / (k + t));
            add(refraction, nodes[c].subtotal, t / (k + t));
            total = 1;
        } else if (nodes[c].kind == RT_RAY_REFLECTED) {
            add(reflection, nodes[c].subtotal, 1);
        }
    }
    return total;
}
