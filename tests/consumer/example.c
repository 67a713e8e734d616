/* Renders a scene file to a binary PPM: example SCENE.scn OUT.ppm */
#include <stdio.h>

#include <raytrace/raytrace.h>

int main(int argc, char **argv)
{
    rt_scene *scene;
    rt_scene_info info = {.size = sizeof info};
    rt_image image;
    rt_error error;
    rt_status status;

    if (argc != 3) {
        fprintf(stderr, "usage: %s SCENE.scn OUT.ppm\n", argv[0]);
        return 2;
    }
    if (rt_scene_load(argv[1], NULL, &scene, &error) != RT_OK) {
        fprintf(stderr, "%s: %s\n", argv[0], error.message);
        return 1;
    }
    rt_scene_get_info(scene, &info);
    status = rt_image_init(&image, info.width, info.height, &error);
    if (status == RT_OK)
        status = rt_render(scene, NULL, &image, &error);  /* default options */
    if (status == RT_OK)
        status = rt_image_save(argv[2], &image, RT_IMAGE_P6, NULL, &error);
    if (status == RT_OK)
        printf("%s\n", argv[2]);
    else
        fprintf(stderr, "%s: %s\n", argv[0], error.message);
    rt_image_release(&image);
    rt_scene_destroy(scene);
    return status == RT_OK ? 0 : 1;
}
