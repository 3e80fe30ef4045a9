#version 330 core
// Static lit geometry: the table (cloth, cushions, rails, pits) and the cue stick.
layout(location = 0) in vec3 aPosition;  // m
layout(location = 1) in vec3 aNormal;
layout(location = 2) in vec3 aColour;
layout(location = 3) in float aMaterial; // SurfaceMaterial

uniform mat4 uViewProjection;
uniform mat4 uModel;

out vec3 vWorld;
out vec3 vNormal;
out vec3 vColour;
flat out int vMaterial;

void main()
{
    vec4 world = uModel * vec4(aPosition, 1.0);
    vWorld = world.xyz;
    vNormal = mat3(uModel) * aNormal;
    vColour = aColour;
    vMaterial = int(aMaterial + 0.5);
    gl_Position = uViewProjection * world;
}
