#version 330 core
// Overlay lines (paths, arrows, markers): widened to screen-space quads by line.geom.
layout(location = 0) in vec3 aPosition;     // m
layout(location = 1) in vec4 aColour;       // rgba
layout(location = 2) in vec2 aTimeDistance; // s (when the point is reached; < 0 = always past), m along the path

uniform mat4 uViewProjection;

out vec4 gColour;
out vec2 gTimeDistance;

void main()
{
    gColour = aColour;
    gTimeDistance = aTimeDistance;
    gl_Position = uViewProjection * vec4(aPosition, 1.0);
}
