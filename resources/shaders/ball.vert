#version 330 core
// Instanced balls: a unit sphere scaled and placed per instance. The orientation quaternion turns
// the surface point into the ball's own frame, where the number, stripe and dots are painted.
layout(location = 0) in vec3 aUnit;
layout(location = 1) in vec4 iCentreRadius;  // m
layout(location = 2) in vec4 iOrientation;   // quaternion (x, y, z, w), body -> world
layout(location = 3) in vec4 iColourNumber;  // rgb, number (0 = none)
layout(location = 4) in vec4 iFlags;         // striped, dotted, highlighted, alpha

uniform mat4 uViewProjection;

out vec3 vWorld;
out vec3 vNormal;
out vec3 vLocal;
flat out vec4 vColourNumber;
flat out vec4 vFlags;

// Rotates v by the inverse of the unit quaternion q.
vec3 rotateInverse(vec4 q, vec3 v)
{
    vec3 u = -q.xyz;
    return v + 2.0 * cross(u, cross(u, v) + q.w * v);
}

void main()
{
    vWorld = iCentreRadius.xyz + iCentreRadius.w * aUnit;
    vNormal = aUnit;
    vLocal = rotateInverse(iOrientation, aUnit);
    vColourNumber = iColourNumber;
    vFlags = iFlags;
    gl_Position = uViewProjection * vec4(vWorld, 1.0);
}
