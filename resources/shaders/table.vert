#version 330 core
// Static lit geometry: the table (cloth, cushions, rails, pits) and the cue stick. Lighting is
// evaluated per vertex (the meshes are finely subdivided where the lamps' falloff varies): a software
// rasteriser cannot afford two Phong lights on every pixel of a full-screen table at 60 frames per
// second.
layout(location = 0) in vec3 aPosition;  // m
layout(location = 1) in vec3 aNormal;
layout(location = 2) in vec3 aColour;
layout(location = 3) in float aMaterial; // SurfaceMaterial

uniform mat4 uViewProjection;
uniform mat4 uModel;
uniform vec3 uEye;        // m
uniform vec3 uLights[2];  // m, lamp positions

out vec3 vWorld;
out vec3 vLit;
flat out int vMaterial;

const int CLOTH = 0, CUSHION = 1, WOOD = 2, PIT = 3, SIGHT = 4;

void main()
{
    vec4 world = uModel * vec4(aPosition, 1.0);
    vWorld = world.xyz;
    vMaterial = int(aMaterial + 0.5);
    vec3 n = normalize(mat3(uModel) * aNormal);
    vec3 toEye = normalize(uEye - world.xyz);
    if (dot(n, toEye) < 0.0 && vMaterial == PIT) n = -n;
    float specular = 0.35, shininess = 40.0;
    vec3 base = aColour;
    if (vMaterial == CLOTH || vMaterial == CUSHION || vMaterial == PIT) specular = 0.0;
    else if (vMaterial == WOOD) { specular = 0.35; shininess = 30.0; }
    else if (vMaterial == SIGHT) { specular = 0.6; shininess = 60.0; }
    if (vMaterial == PIT) base *= 0.25 + 0.75 * clamp(1.0 + world.z / 0.1, 0.0, 1.0);  // darker the deeper
    vec3 light = vec3(0.28) * base;
    for (int i = 0; i < 2; ++i) {
        vec3 d = uLights[i] - world.xyz;
        float falloff = 1.0 / (1.0 + 0.35 * dot(d.xy, d.xy));
        vec3 l = normalize(d);
        light += falloff * 0.55 * max(dot(n, l), 0.0) * base;
        if (specular > 0.0) light += falloff * specular * pow(max(dot(reflect(-l, n), toEye), 0.0), shininess) * vec3(1.0);
    }
    vLit = light;
    gl_Position = uViewProjection * world;
}
