#version 330 core
// Phong lighting under two lamps over the table. Cloth, cushions and rails are cut away inside the
// pocket circles, which opens the pits below them.
in vec3 vWorld;
in vec3 vNormal;
in vec3 vColour;
flat in int vMaterial;

uniform vec3 uEye;
uniform vec3 uLights[2];   // m, lamp positions
uniform vec3 uPockets[6];  // centre x, y and radius, m
uniform int uPocketCount;
uniform vec2 uTableSize;   // m, the playing surface

out vec4 fragColour;

const int CLOTH = 0, CUSHION = 1, WOOD = 2, PIT = 3, SIGHT = 4;

void main()
{
    // Only fragments near the table's edge can lie in a pocket circle (every pocket centre lies on or
    // outside the cushion noses, and no pocket is wider than 0.1 m): the test skips the loop elsewhere.
    vec2 inner = min(vWorld.xy, uTableSize - vWorld.xy);
    if (vMaterial <= WOOD && min(inner.x, inner.y) < 0.1) {
        for (int i = 0; i < uPocketCount; ++i) {
            if (distance(vWorld.xy, uPockets[i].xy) < uPockets[i].z) discard;
        }
    }
    vec3 base = vColour;
    float specular = 0.35, shininess = 40.0;
    if (vMaterial == CLOTH || vMaterial == CUSHION) {
        specular = 0.0;
    } else if (vMaterial == WOOD) {
        // Grain running along each rail: long rails beyond y = 0 and y = W, short ones beyond x.
        bool longRail = vWorld.y < 0.0 || vWorld.y > uTableSize.y;
        float across = longRail ? vWorld.y : vWorld.x;
        float along = longRail ? vWorld.x : vWorld.y;
        float grain = sin(700.0 * across + 3.0 * sin(4.0 * along + 40.0 * across));
        float figure = sin(55.0 * across + 1.5 * sin(2.5 * along));
        base *= 0.9 + 0.05 * grain + 0.07 * figure;
        specular = 0.45;
        shininess = 50.0;
    } else if (vMaterial == PIT) {
        // Darker the deeper: the pit reads as a hole.
        base *= 0.25 + 0.75 * clamp(1.0 + vWorld.z / 0.1, 0.0, 1.0);
        specular = 0.0;
    } else if (vMaterial == SIGHT) {
        specular = 0.6;
        shininess = 60.0;
    }

    vec3 n = normalize(vNormal);
    vec3 toEye = normalize(uEye - vWorld);
    if (dot(n, toEye) < 0.0) n = -n;
    vec3 light = vec3(0.28) * base;
    for (int i = 0; i < 2; ++i) {
        vec3 d = uLights[i] - vWorld;
        float falloff = 1.0 / (1.0 + 0.35 * dot(d.xy, d.xy));
        vec3 l = normalize(d);
        float diffuse = max(dot(n, l), 0.0);
        light += falloff * 0.55 * diffuse * base;
        if (specular > 0.0) light += falloff * specular * pow(max(dot(reflect(-l, n), toEye), 0.0), shininess) * vec3(1.0);
    }
    fragColour = vec4(light, 1.0);
}
