#version 330 core
// Phenolic balls: glossy Phong, a band for stripes, a white disc with the number on both ends of the
// body x axis, red dots on the cue ball's six axes.
in vec3 vWorld;
in vec3 vNormal;
in vec3 vLocal;
flat in vec4 vColourNumber;
flat in vec4 vFlags;

uniform vec3 uEye;
uniform vec3 uLights[2];
uniform sampler2D uDigits;  // 4 x 4 cells, the numbers 0-15 as coverage in the red channel

out vec4 fragColour;

const vec3 WHITE = vec3(0.95, 0.94, 0.89);
const float DISC_COS = 0.9;     // angular radius of the number disc: acos(0.9) = 25.8 deg
const float DISC_SIN = 0.43589; // sin(acos(0.9))

void main()
{
    vec3 n = normalize(vNormal);
    vec3 l = normalize(vLocal);
    vec3 base = vColourNumber.rgb;
    float aa = 0.02;
    if (vFlags.x > 0.5) base = mix(base, WHITE, smoothstep(0.52 - aa, 0.52 + aa, abs(l.z)));
    if (vFlags.y > 0.5) {
        vec3 a = abs(l);
        float m = max(a.x, max(a.y, a.z));
        base = mix(base, vec3(0.75, 0.05, 0.05), smoothstep(0.980, 0.984, m));
    }
    int number = int(vColourNumber.a + 0.5);
    if (number > 0) {
        float c = abs(l.x);
        float disc = smoothstep(DISC_COS - 0.006, DISC_COS + 0.006, c);
        // Disc coordinates, upright when the disc is seen from outside with the body z axis up.
        vec2 uv = vec2(l.y * sign(l.x), l.z) / DISC_SIN * 0.62;
        vec2 cell = vec2(float(number % 4), float(number / 4));
        vec2 atlas = (cell + vec2(0.5 + 0.5 * uv.x, 0.5 - 0.5 * uv.y)) / 4.0;
        float ink = (abs(uv.x) < 1.0 && abs(uv.y) < 1.0) ? texture(uDigits, atlas).r : 0.0;
        base = mix(base, mix(WHITE, vec3(0.02), ink), disc);
    }

    vec3 toEye = normalize(uEye - vWorld);
    vec3 light = 0.22 * base;
    for (int i = 0; i < 2; ++i) {
        vec3 d = uLights[i] - vWorld;
        float falloff = 1.0 / (1.0 + 0.35 * dot(d.xy, d.xy));
        vec3 dir = normalize(d);
        float diffuse = max(dot(n, dir), 0.0);
        float spec = pow(max(dot(reflect(-dir, n), toEye), 0.0), 90.0);
        light += falloff * (0.75 * diffuse * base + 0.8 * spec * vec3(1.0));
    }
    // A faint reflection of the room at grazing angles.
    float rim = pow(1.0 - max(dot(n, toEye), 0.0), 3.0);
    light += 0.08 * rim * vec3(0.8, 0.85, 0.9);
    if (vFlags.z > 0.5) light += rim * vec3(1.0, 0.85, 0.2) + 0.08 * vec3(1.0, 0.9, 0.4);
    fragColour = vec4(light, vFlags.w);
}
