/*
 * cli_explain.c - a ray tree's rays and terms as the rendering model names
 * them, and the explanation as text or JSON (see cli_explain.h).  Text
 * shows 6 significant digits (the pixel's value 17, all of them); JSON
 * 17 everywhere, so that a reader gets the doubles back exactly.
 */
#include "cli_explain.h"

#include "cli_text.h"

/* Each rt_ray_kind's name, in the text and in the JSON. */
static const char *const kind_names[] = {"camera", "shadow", "reflected",
                                         "refracted"};

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
    return nodes[parent].hit && nodes[parent].transparency > 0 &&
           child_of(nodes, count, parent, RT_RAY_REFRACTED) < 0;
}

const char *cli_explain_ray_name(const rt_ray_node *nodes, size_t count,
                                 size_t i)
{
    if (cli_explain_total_reflection(nodes, count, i))
        return "totally reflected";
    return kind_names[nodes[i].kind];
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
            double k = nodes[i].reflection, t = nodes[i].transparency;
            add(reflection, nodes[c].subtotal, k / (k + t));
            add(refraction, nodes[c].subtotal, t / (k + t));
            total = 1;
        } else if (nodes[c].kind == RT_RAY_REFLECTED) {
            add(reflection, nodes[c].subtotal, 1);
        }
    }
    return total;
}

/* ------------------------------------------------------------------ */
/* Text                                                                */

static void print_vec(FILE *out, const char *label, rt_vec3 v)
{
    fprintf(out, "%s(%.6g, %.6g, %.6g)", label, v.x, v.y, v.z);
}

static void print_color(FILE *out, const char *label, rt_color c)
{
    fprintf(out, "%s%.6g %.6g %.6g", label, c.r, c.g, c.b);
}

static void print_shadow_ray(FILE *out, const rt_ray_node *n,
                             const rt_ray_node *r, int indent)
{
    const rt_ray_node *hit = r->parent >= 0 ? &n[r->parent] : NULL;
    int shiny = hit != NULL && hit->highlight > 0;
    fprintf(out, "%*sshadow ray to light %d: N.S %.6g, ", 2 * indent, "",
            r->light, r->n_dot_s);
    if (!r->cast)
        fprintf(out, "not cast (%s), term 0\n",
                r->diffuse == 0 && r->n_dot_s > 0 ? "d = 0" : "N.S <= 0");
    else if (r->e > 0 && shiny) {
        rt_color diffuse = {r->own.r - r->highlight_own.r,
                            r->own.g - r->highlight_own.g,
                            r->own.b - r->highlight_own.b};
        print_color(out, "E 1 (lit): E (N.S) d C_S C_F / 255 x weight = ",
                    diffuse);
        fprintf(out, "\n%*s", 2 * indent + 2, "");
        fprintf(out, "highlight: R.V %.6g, E s max(0, R.V)^p C_S x weight "
                     "= ", r->r_dot_v);
        print_color(out, "", r->highlight_own);
        print_color(out, "; term ", r->own);
        fprintf(out, "\n");
    } else if (r->e > 0) {
        print_color(out, "E 1 (lit): E (N.S) d C_S C_F / 255 x weight = ",
                    r->own);
        fprintf(out, "\n");
    } else if (r->blocker >= 0)
        fprintf(out, "E 0, shadowed by facet %d (line %d), term 0\n",
                r->blocker, r->blocker_line);
    else
        fprintf(out, "E 0 (shadowed), term 0\n");
}

/* Ray i and the rays that come from it, indented by their depth. */
static void print_ray(FILE *out, const rt_ray_node *n, size_t count,
                      size_t i, int indent)
{
    const rt_ray_node *r = &n[i];
    if (r->kind == RT_RAY_SHADOW) {
        print_shadow_ray(out, n, r, indent);
        return;
    }
    fprintf(out, "%*s%s ray", 2 * indent, "",
            cli_explain_ray_name(n, count, i));
    if (r->kind != RT_RAY_CAMERA)
        fprintf(out, " (weight %.6g)", r->weight);
    print_vec(out, " from ", r->origin);
    print_vec(out, " direction ", r->direction);
    fprintf(out, "\n%*s", 2 * indent + 2, "");
    if (!r->hit) {
        print_color(out, "hits nothing: background x weight = ", r->own);
        fprintf(out, "\n");
        return;
    }
    fprintf(out, "hits facet %d (line %d) at t %.6g", r->facet, r->line,
            r->t);
    print_vec(out, ", point ", r->point);
    print_vec(out, ", normal as used ", r->normal);
    fprintf(out, "; k %.6g, t %.6g, d %.6g", r->reflection, r->transparency,
            r->diffuse);
    if (r->highlight > 0)
        fprintf(out, ", highlight s %.6g, p %.6g", r->highlight,
                r->highlight_exponent);
    fprintf(out, "\n");
    if (r->smooth) {
        fprintf(out, "%*s", 2 * indent + 2, "");
        print_vec(out, "smooth: shading normal N_s ", r->shading_normal);
        print_vec(out, ", shading point P' ", r->shading_point);
        fprintf(out, "\n");
    }
    for (size_t c = i + 1; c < count; c++)
        if (n[c].parent == (int)i)
            print_ray(out, n, count, c, indent + 1);
    rt_color direct, reflected, refracted;
    int total = cli_explain_terms(n, count, i, &direct, &reflected,
                                  &refracted);
    fprintf(out, "%*s", 2 * indent + 2, "");
    print_color(out, "terms: direct light ", direct);
    print_color(out, " + reflection k C_R ", reflected);
    print_color(out, " + refraction t C_T ", refracted);
    print_color(out, " = ", r->subtotal);
    fprintf(out, "%s\n", total ? " (total internal reflection: C_T is the "
                                 "colour of the mirror ray, which carries "
                                 "k C_R + t C_T)"
                               : "");
}

void cli_explain_print_text(FILE *out, const rt_ray_tree *tree,
                            const char *scene, int x, int y, int samples)
{
    size_t count;
    const rt_ray_node *n = rt_ray_tree_nodes(tree, &count);
    char shown[1024];
    int shiny = 0;
    for (size_t i = 0; i < count; i++)
        shiny |= n[i].hit && n[i].highlight > 0;
    fprintf(out, "pixel %d,%d of %s: C = sum over lights of E (N.S) d C_S "
                 "C_F / 255%s + k C_R + t C_T\n", x, y,
            cli_printable(scene, shown, sizeof shown),
            shiny ? " + E s max(0, R.V)^p C_S" : "");
    for (size_t i = 0; i < count; i++)
        if (n[i].parent < 0) {
            if (samples > 1)
                fprintf(out, "sample %d:\n", n[i].sample);
            print_ray(out, n, count, i, 1);
        }
    if (rt_ray_tree_truncated(tree) > 0)
        fprintf(out, "  (%zu rays left out: the tree is too large to "
                     "show)\n", rt_ray_tree_truncated(tree));
    rt_color v = rt_ray_tree_value(tree);
    fprintf(out, "pixel value %.17g %.17g %.17g%s -> bytes %d %d %d\n", v.r,
            v.g, v.b, samples > 1 ? " (the mean of the samples)" : "",
            rt_channel_to_byte(v.r), rt_channel_to_byte(v.g),
            rt_channel_to_byte(v.b));
}

/* ------------------------------------------------------------------ */
/* JSON                                                                */

static void print_json_vec(FILE *out, const char *name, rt_vec3 v)
{
    fprintf(out, ",\"%s\":[%.17g,%.17g,%.17g]", name, v.x, v.y, v.z);
}

static void print_json_color(FILE *out, const char *name, rt_color c)
{
    fprintf(out, ",\"%s\":[%.17g,%.17g,%.17g]", name, c.r, c.g, c.b);
}

/* The fields of a camera, reflected or refracted ray. */
static void print_json_trace(FILE *out, const rt_ray_node *n, size_t count,
                             size_t i)
{
    const rt_ray_node *r = &n[i];
    fprintf(out, ",\"hit\":%d", r->hit);
    if (r->kind == RT_RAY_REFLECTED)
        fprintf(out, ",\"total_internal_reflection\":%s",
                cli_explain_total_reflection(n, count, i) ? "true"
                                                          : "false");
    if (!r->hit)
        return;
    fprintf(out, ",\"facet\":%d,\"line\":%d,\"t\":%.17g", r->facet,
            r->line, r->t);
    print_json_vec(out, "point", r->point);
    print_json_vec(out, "normal", r->normal);
    fprintf(out, ",\"k\":%.17g,\"transmission\":%.17g,\"d\":%.17g",
            r->reflection, r->transparency, r->diffuse);
    if (r->smooth) {
        fprintf(out, ",\"smooth\":true");
        print_json_vec(out, "shading_normal", r->shading_normal);
        print_json_vec(out, "shading_point", r->shading_point);
    }
    if (r->highlight > 0)
        fprintf(out, ",\"s\":%.17g,\"p\":%.17g", r->highlight,
                r->highlight_exponent);
    rt_color direct, reflected, refracted;
    cli_explain_terms(n, count, i, &direct, &reflected, &refracted);
    print_json_color(out, "direct", direct);
    print_json_color(out, "reflection", reflected);
    print_json_color(out, "refraction", refracted);
}

void cli_explain_print_json(FILE *out, const rt_ray_tree *tree,
                            const char *scene, int x, int y)
{
    size_t count;
    const rt_ray_node *n = rt_ray_tree_nodes(tree, &count);
    rt_color v = rt_ray_tree_value(tree);
    fprintf(out, "{\"scene\":");
    cli_json_string(out, scene);
    fprintf(out, ",\"x\":%d,\"y\":%d", x, y);
    print_json_color(out, "value", v);
    fprintf(out, ",\"bytes\":[%d,%d,%d],\"truncated\":%zu,\"rays\":[",
            rt_channel_to_byte(v.r), rt_channel_to_byte(v.g),
            rt_channel_to_byte(v.b), rt_ray_tree_truncated(tree));
    for (size_t i = 0; i < count; i++) {
        const rt_ray_node *r = &n[i];
        fprintf(out, "%s{\"kind\":\"%s\",\"parent\":%d,\"depth\":%d,"
                     "\"sample\":%d,\"weight\":%.17g", i ? "," : "",
                kind_names[r->kind], r->parent, r->depth, r->sample,
                r->weight);
        print_json_vec(out, "origin", r->origin);
        print_json_vec(out, "direction", r->direction);
        if (r->kind == RT_RAY_SHADOW)
            fprintf(out, ",\"light\":%d,\"n_dot_s\":%.17g,\"cast\":%d,"
                         "\"e\":%g,\"blocker\":%d,\"blocker_line\":%d",
                    r->light, r->n_dot_s, r->cast, r->e, r->blocker,
                    r->blocker_line);
        if (r->kind == RT_RAY_SHADOW && r->parent >= 0 &&
            n[r->parent].highlight > 0) {
            fprintf(out, ",\"r_dot_v\":%.17g", r->r_dot_v);
            print_json_color(out, "highlight", r->highlight_own);
        }
        else
            print_json_trace(out, n, count, i);
        print_json_color(out, "own", r->own);
        print_json_color(out, "subtotal", r->subtotal);
        fprintf(out, "}");
    }
    fprintf(out, "]}\n");
}
