#version 330 core
// A soft contact shadow on the cloth under each ball (the lamps hang right above the table).
layout(location = 0) in vec2 aCorner;        // [-1, 1]^2
layout(location = 1) in vec4 iCentreRadius;  // m

uniform mat4 uViewProjection;

out vec2 vCorner;
out float vStrength;  // 1 for a ball on the cloth, less the higher it flies

void main()
{
    vCorner = aCorner;
    // A flying ball's shadow stays on the cloth, wider and fainter with its height above its rest.
    float lift = max(iCentreRadius.z - iCentreRadius.w, 0.0) / iCentreRadius.w;
    float spread = 1.0 + 0.35 * lift;
    vStrength = 1.0 / (spread * spread);
    vec3 world = vec3(iCentreRadius.xy + 1.5 * spread * iCentreRadius.w * aCorner, 0.0004);
    gl_Position = uViewProjection * vec4(world, 1.0);
}
