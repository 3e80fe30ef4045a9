#version 330 core
// A soft contact shadow on the cloth under each ball (the lamps hang right above the table).
layout(location = 0) in vec2 aCorner;        // [-1, 1]^2
layout(location = 1) in vec4 iCentreRadius;  // m

uniform mat4 uViewProjection;

out vec2 vCorner;

void main()
{
    vCorner = aCorner;
    vec3 world = vec3(iCentreRadius.xy + 1.5 * iCentreRadius.w * aCorner, 0.0004);
    gl_Position = uViewProjection * vec4(world, 1.0);
}
