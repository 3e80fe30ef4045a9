#version 330 core
// Cloth, cushions and rails are cut away inside the pocket circles, which opens the pits below them
// (only in the variant built with CUT_POCKETS, drawn for the triangles near a pocket: a shader that may
// discard costs a software rasteriser its fast paths); the rails get a wood grain along each rail.
in vec3 vWorld;
in vec3 vLit;
flat in int vMaterial;

uniform vec3 uPockets[6];  // centre x, y and radius, m, by place: bottom left, middle, right, then top
uniform int uPocketCount;  // 0 or 6
uniform vec2 uTableSize;   // m, the playing surface

out vec4 fragColour;

const int WOOD = 2;

void main()
{
#ifdef CUT_POCKETS
    // Only the pocket of the fragment's sixth of the table can contain it: one test, not six.
    if (vMaterial <= WOOD && uPocketCount == 6) {
        int column = vWorld.x < 0.25 * uTableSize.x ? 0 : (vWorld.x > 0.75 * uTableSize.x ? 2 : 1);
        int row = vWorld.y < 0.5 * uTableSize.y ? 0 : 1;
        vec3 pocket = uPockets[3 * row + column];
        vec2 d = vWorld.xy - pocket.xy;
        if (dot(d, d) < pocket.z * pocket.z) discard;
    }
#endif
    vec3 colour = vLit;
    if (vMaterial == WOOD) {
        bool longRail = vWorld.y < 0.0 || vWorld.y > uTableSize.y;
        float across = longRail ? vWorld.y : vWorld.x;
        float along = longRail ? vWorld.x : vWorld.y;
        // Triangle waves, not sines: a software rasteriser pays dearly for transcendentals.
        float grain = abs(fract(110.0 * across + 0.3 * fract(0.6 * along)) - 0.5);
        float figure = abs(fract(9.0 * across + 0.25 * abs(fract(0.4 * along) - 0.5)) - 0.5);
        colour *= 0.86 + 0.12 * grain + 0.16 * figure;
    }
    fragColour = vec4(colour, 1.0);
}
