#version 330 core
// Instanced balls as impostors: one camera-facing quad per ball, the sphere ray-traced exactly in
// ball.frag (two triangles per ball instead of a tessellated sphere: software rasterisers are bound
// by triangle setup). The orientation quaternion turns the surface point into the ball's own frame,
// where the number, stripe and dots are painted.
layout(location = 0) in vec2 aCorner;        // [-1, 1]^2
layout(location = 1) in vec4 iCentreRadius;  // m
layout(location = 2) in vec4 iOrientation;   // quaternion (x, y, z, w), body -> world
layout(location = 3) in vec4 iColourNumber;  // rgb, number (0 = none)
layout(location = 4) in vec4 iFlags;         // striped, dotted, highlighted, alpha

uniform mat4 uViewProjection;
uniform vec3 uEye;       // m
uniform vec3 uCameraUp;  // unit, world

out vec3 vQuadPoint;
flat out vec4 vCentreRadius;
flat out vec4 vOrientation;
flat out vec4 vColourNumber;
flat out vec4 vFlags;

void main()
{
    vec3 c = iCentreRadius.xyz;
    float r = iCentreRadius.w;
    vec3 toEye = uEye - c;
    float d = length(toEye);
    toEye /= d;
    vec3 right = normalize(cross(uCameraUp, toEye));
    vec3 up = cross(toEye, right);
    // The silhouette of a sphere seen from distance d has radius r d / sqrt(d^2 - r^2) in the plane
    // through its centre; a little more leaves room for the antialiased edge.
    float s = 1.08 * r * d / sqrt(max(d * d - r * r, 1e-10));
    // The quad stands on the eye's side of the sphere, so that it is not clipped away by what lies
    // just behind the ball; the depth written is the sphere's own.
    vQuadPoint = c + r * toEye + s * (aCorner.x * right + aCorner.y * up) * (d - r) / d;
    vCentreRadius = iCentreRadius;
    vOrientation = iOrientation;
    vColourNumber = iColourNumber;
    vFlags = iFlags;
    gl_Position = uViewProjection * vec4(vQuadPoint, 1.0);
}
