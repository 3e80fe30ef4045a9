#version 330 core
// Cloth, cushions and rails are cut away inside the pocket circles, which opens the pits below them;
// the rails get a wood grain running along each rail.
in vec3 vWorld;
in vec3 vLit;
flat in int vMaterial;

uniform vec3 uPockets[6];  // centre x, y and radius, m
uniform int uPocketCount;
uniform vec2 uTableSize;   // m, the playing surface

out vec4 fragColour;

const int WOOD = 2;

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
    vec3 colour = vLit;
    if (vMaterial == WOOD) {
        bool longRail = vWorld.y < 0.0 || vWorld.y > uTableSize.y;
        float across = longRail ? vWorld.y : vWorld.x;
        float along = longRail ? vWorld.x : vWorld.y;
        float grain = sin(700.0 * across + 3.0 * sin(4.0 * along + 40.0 * across));
        float figure = sin(55.0 * across + 1.5 * sin(2.5 * along));
        colour *= 0.9 + 0.05 * grain + 0.07 * figure;
    }
    fragColour = vec4(colour, 1.0);
}
